// libFuzzer target: grid files through loadGrid (the first byte picks the format). Built with
// VISSORT_FUZZ=ON; run by scripts/fuzz.sh.

#include "fuzz_entry_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    vissort::fuzz::gridFile(data, size);
    return 0;
}
