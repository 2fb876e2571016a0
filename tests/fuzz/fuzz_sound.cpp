// libFuzzer harness: see build-fuzzers.sh.
#include "FuzzTargets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)stoa::fuzz::sound(data, size);
    return 0;
}
