#pragma once

#include <filesystem>
#include <string>

#include "framework/core/export.h"

namespace fitfeel {

// The phrase of a path with nothing there, for callers that word that case their own way.
inline constexpr const char* kDoesNotExist = "does not exist";

// Why `file` cannot be read as a regular file, as a phrase to follow the path in a message ("'a.csv'
// cannot be opened: too many levels of symbolic links"), or empty when it can: "does not exist",
// "is a folder", "is not a regular file (a device, pipe or socket)", "cannot be opened: <the OS's
// reason>". The reasons are those stat(2) and open(2) gave for this very file: a symlink loop reads
// as a loop, an unreadable file as "permission denied".
FITFEEL_API std::string WhyNotReadableFile(const std::filesystem::path& file);

// Why `folder` is not an existing folder, as the same kind of phrase ("does not exist", "is not a
// folder", "cannot be opened: <the OS's reason>"), or empty when it is one.
FITFEEL_API std::string WhyNotFolder(const std::filesystem::path& folder);

}  // namespace fitfeel
