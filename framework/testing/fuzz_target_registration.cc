// Compiled once per libFuzzer target into the replay driver, with the target's own definitions:
// LLVMFuzzerTestOneInput renamed to an entry point of the target's own and FITFEEL_FUZZ_TARGET its
// name (cmake/FitfeelTargets.cmake). Registers the one under the other.
#include <cstddef>
#include <cstdint>

#include "framework/testing/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {
[[maybe_unused]] const bool kRegistered =
    fitfeel::test_support::RegisterFuzzTarget(FITFEEL_FUZZ_TARGET, &LLVMFuzzerTestOneInput);
}  // namespace
