// libFuzzer target: built-in scene specifications (builtin:NAME?k=v&...). Built with
// VISSORT_FUZZ=ON; run by scripts/fuzz.sh.

#include "fuzz_entry_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    vissort::fuzz::sceneParameters(data, size);
    return 0;
}
