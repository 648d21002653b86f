#include "framework/core/path_check.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "framework/core/os_reason.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// Empty and the status when the path can be looked at, else why not.
std::string Look(const fs::path& path, fs::file_status* status) {
  std::error_code ec;
  *status = fs::status(path, ec);
  if (status->type() == fs::file_type::not_found) return kDoesNotExist;
  if (ec) return "cannot be opened: " + OsReason(ec);
  return "";
}

}  // namespace

std::string WhyNotReadableFile(const fs::path& file) {
  fs::file_status status;
  if (std::string why = Look(file, &status); !why.empty()) return why;
  if (fs::is_directory(status)) return "is a folder";
  if (!fs::is_regular_file(status)) return "is not a regular file (a device, pipe or socket)";
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "cannot be opened: " + OsReason(errno);
  ::close(fd);
  return "";
}

std::string WhyNotFolder(const fs::path& folder) {
  fs::file_status status;
  if (std::string why = Look(folder.empty() ? fs::path(".") : folder, &status); !why.empty()) {
    return why;
  }
  return fs::is_directory(status) ? "" : "is not a folder";
}

}  // namespace fitfeel
