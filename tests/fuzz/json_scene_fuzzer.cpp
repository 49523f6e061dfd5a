// libFuzzer target: JSON scene files. Built with VISSORT_FUZZ=ON; run by scripts/fuzz.sh.

#include "fuzz_entry_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    vissort::fuzz::jsonScene(data, size);
    return 0;
}
