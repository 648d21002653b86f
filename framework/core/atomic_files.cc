#include "framework/core/atomic_files.h"

#include <cerrno>
#include <fstream>
#include <system_error>

#include "framework/core/error.h"
#include "framework/core/os_reason.h"
#include "framework/core/temporary_files.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

void WriteOne(const fs::path& path, const std::string& text) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  const int open_error = errno;
  if (!out) throw UserError("cannot create '" + path.string() + "': " + OsReason(open_error));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw UserError("cannot write '" + path.string() + "' (disk full?)");
}

}  // namespace

void WriteFilesAtomically(const fs::path& dir,
                          const std::vector<std::pair<std::string, std::string>>& files) {
  for (const auto& [name, content] : files) {
    if (name.empty() || fs::path(name).filename() != fs::path(name)) {
      throw UserError("internal: '" + name + "' is not a plain file name");
    }
  }
  std::error_code ec;
  const bool created_dir = !fs::exists(dir, ec);
  if (created_dir && !fs::create_directories(dir, ec) && ec) {
    throw UserError("cannot create output folder '" + dir.string() + "': " + ec.message());
  }
  if (!fs::is_directory(dir, ec)) {
    throw UserError("output path '" + dir.string() + "' is not a folder");
  }
  std::vector<fs::path> temporaries;
  std::vector<fs::path> renamed;
  try {
    for (const auto& [name, content] : files) {
      temporaries.push_back(TemporaryPathFor(dir / name));
      WriteOne(temporaries.back(), content);
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
      const fs::path final_path = dir / files[i].first;
      fs::rename(temporaries[i], final_path, ec);
      if (ec) {
        throw UserError("cannot move '" + temporaries[i].string() + "' to '" +
                        final_path.string() + "': " + ec.message());
      }
      renamed.push_back(final_path);
    }
  } catch (...) {
    for (const auto& p : temporaries) fs::remove(p, ec);
    for (const auto& f : renamed) fs::remove(f, ec);
    if (created_dir) fs::remove(dir, ec);  // only removes it if empty
    throw;
  }
}

}  // namespace fitfeel
