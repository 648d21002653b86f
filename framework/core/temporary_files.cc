#include "framework/core/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <optional>
#include <string_view>
#include <system_error>

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMarker = ".tmp-";
constexpr std::string_view kPartial = ".partial";

// The process number of a temporary's name, nullopt when the name is not one.
std::optional<long> TemporaryOwner(std::string_view name) {
  if (name.size() < 2 || name.front() != '.') return std::nullopt;
  if (name.ends_with(kPartial)) name.remove_suffix(kPartial.size());
  const std::size_t marker = name.rfind(kMarker);
  // ".X.tmp-N": at least one character of the final name between the dot and the marker.
  if (marker == std::string_view::npos || marker < 2) return std::nullopt;
  const std::string_view digits = name.substr(marker + kMarker.size());
  if (digits.empty() || digits.size() > 9) return std::nullopt;
  long pid = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    pid = pid * 10 + (c - '0');
  }
  if (pid <= 0) return std::nullopt;
  return pid;
}

bool Running(long pid) {
  if (pid == static_cast<long>(::getpid())) return false;
  // Signal 0 checks only: EPERM is a running process of another user.
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

}  // namespace

fs::path TemporaryPathFor(const fs::path& file) {
  return file.parent_path() /
         ("." + file.filename().string() + std::string(kMarker) + std::to_string(::getpid()));
}

StaleTemporaries RemoveStaleTemporaries(const fs::path& folder) {
  StaleTemporaries stale;
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const fs::path& path = it->path();
    const std::optional<long> pid = TemporaryOwner(path.filename().string());
    std::error_code type_ec;
    if (!pid || !it->is_regular_file(type_ec) || Running(*pid)) continue;
    std::error_code remove_ec;
    if (fs::remove(path, remove_ec)) {
      stale.removed.push_back(path);
      if (std::find(stale.processes.begin(), stale.processes.end(), *pid) ==
          stale.processes.end()) {
        stale.processes.push_back(*pid);
      }
    } else if (remove_ec) {
      stale.failures.push_back(path.string() + ": " + remove_ec.message());
    }
  }
  std::sort(stale.removed.begin(), stale.removed.end());
  std::sort(stale.processes.begin(), stale.processes.end());
  return stale;
}

}  // namespace fitfeel
