#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/export.h"

namespace fitfeel {

// Writes a set of files into `dir` (created if missing) all or nothing: each under a temporary
// name in `dir`, then renamed into place once every one is complete. On any failure the
// temporaries, the files renamed so far and a `dir` this call created are removed, and UserError
// is thrown: a reader never sees a half-written set. `files` holds (name, content) pairs; names
// are plain file names inside `dir`.
FITFEEL_API void WriteFilesAtomically(
    const std::filesystem::path& dir,
    const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace fitfeel
