#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/export.h"

namespace fitfeel {

// The name a file has while it is written, in the folder it goes to: ".NAME.tmp-PID", renamed to
// NAME once complete. Hidden, so that a listing of the folder shows finished files only; the
// process number tells the next command into the folder a leftover of a killed process (SIGKILL
// leaves no chance to clean up) from a file another process is still writing.
FITFEEL_API std::filesystem::path TemporaryPathFor(const std::filesystem::path& file);

// What RemoveStaleTemporaries did.
struct StaleTemporaries {
  std::vector<std::filesystem::path> removed;  // the files removed
  std::vector<long> processes;                 // the dead processes that left them, ascending
  std::vector<std::string> failures;           // "FILE: reason" for each that could not be removed
};

// Removes from `folder` the temporaries of processes that are no longer running: the files named
// like TemporaryPathFor's (also with a ".partial" suffix, a recording's own temporary inside one)
// whose process number is not a running process, or is this process's (a process of that number
// gone long ago: call this before writing into the folder). A temporary of a running process is
// left alone: another fitfeel may be writing into the same folder. A missing folder holds none.
// Never throws: a file that cannot be removed is listed in `failures`.
FITFEEL_API StaleTemporaries RemoveStaleTemporaries(const std::filesystem::path& folder);

}  // namespace fitfeel
