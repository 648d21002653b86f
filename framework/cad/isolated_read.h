#pragma once

// Reading a STEP file at scene load, never in the tick, in a child process with a time limit: a
// file that crashes or hangs Open CASCADE's reader costs that child, and fitfeel reports it as a
// refusal (UserError, exit code 2) instead of going down with it.

#include <cstdint>
#include <filesystem>

#include "framework/cad/cad_document.h"

namespace fitfeel::cad {

struct ReadLimits {
  std::uint64_t max_bytes = std::uint64_t{512} << 20;  // checked before any byte is read
  double seconds = 60.0;                               // the child is killed after this
};

// Checks the file (present, not empty, within max_bytes, a STEP text from its ISO-10303-21 header
// to its END-ISO-10303-21 trailer), then reads it in a forked child and returns what the child
// read. Every failure, the child's crash or timeout included, throws UserError naming the file.
// Forks: call it before the process starts threads. For the tests, the environment variable
// FITFEEL_TEST_CAD_READER set to "abort" or "hang" makes the child abort or hang once forked.
CadDocument ReadStep(const std::filesystem::path& file, const ReadLimits& limits = {});

}  // namespace fitfeel::cad
