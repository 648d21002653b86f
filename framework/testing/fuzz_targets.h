#pragma once

// The libFuzzer targets linked into the replay driver (fuzz_replay_main.cc), by name. In the replay
// build each target's sources are compiled with its entry point renamed, so that the targets link
// into one executable; fuzz_target_registration.cc, compiled beside them, registers the renamed
// entry point under the target's name (cmake/FitfeelTargets.cmake, fitfeel_add_fuzzer).

#include <cstddef>
#include <cstdint>

namespace fitfeel::test_support {

// A target's LLVMFuzzerTestOneInput.
using FuzzTarget = int (*)(const std::uint8_t* data, std::size_t size);

// Registers `target` under `name` (at static initialisation); returns true.
bool RegisterFuzzTarget(const char* name, FuzzTarget target);

}  // namespace fitfeel::test_support
