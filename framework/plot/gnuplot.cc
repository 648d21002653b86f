#include "framework/plot/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "framework/core/error.h"
#include "framework/core/path_check.h"

extern char** environ;

namespace fitfeel::plot {
namespace fs = std::filesystem;

namespace {

std::string ErrnoText(int error) { return std::generic_category().message(error); }

bool IsExecutableFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

std::string ReadWholeFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Closes a descriptor and removes a temporary file unless released.
class TempFileGuard {
 public:
  TempFileGuard(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  ~TempFileGuard() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;
  int CloseFd() {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc;
  }
  void Release() { path_.clear(); }

 private:
  int fd_;
  std::string path_;
};

// Whether gnuplot's stderr says anything about the chart. Fontconfig's own complaints (an
// unwritable font cache in a locked-down CI home, say) concern font lookup, not the data.
bool HasChartMessages(const std::string& messages) {
  std::istringstream lines(messages);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (line.rfind("Fontconfig", 0) == 0) continue;
    return true;
  }
  return false;
}

}  // namespace

std::string_view Extension(ImageFormat format) {
  return format == ImageFormat::kPng ? ".png" : ".svg";
}

std::vector<OutputFile> ResolveOutputs(const fs::path& file) {
  if (file.empty() || file.filename().empty() || file.filename() == "." ||
      file.filename() == "..") {
    throw UserError("output file '" + file.string() + "' does not name a file");
  }
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (const std::string why = WhyNotFolder(folder); !why.empty()) {
    throw UserError("output folder '" + folder.string() + "' " + why);
  }
  const std::string extension = file.extension().string();
  if (extension == ".png") return {{file, ImageFormat::kPng}};
  if (extension == ".svg") return {{file, ImageFormat::kSvg}};
  if (extension.empty()) {
    fs::path png = file, svg = file;
    png += ".png";
    svg += ".svg";
    return {{png, ImageFormat::kPng}, {svg, ImageFormat::kSvg}};
  }
  throw UserError("output file '" + file.string() + "' has the extension '" + extension +
                  "'; expected .png, .svg, or none to write both");
}

std::string QuoteForGnuplot(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\'') {
      quoted += "''";
    } else if (u < 0x20 || u == 0x7f) {
      quoted += ' ';
    } else {
      quoted += c;
    }
  }
  quoted += '\'';
  return quoted;
}

TempDir::TempDir() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = (base != nullptr && *base != '\0') ? base : "/tmp";
  pattern += "/fitfeel-plot-XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) {
    throw std::runtime_error("cannot create a temporary folder from '" + pattern +
                             "': " + ErrnoText(errno));
  }
  path_ = buffer.data();
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::optional<fs::path> Gnuplot::Locate() {
  std::string name = "gnuplot";
  if (const char* chosen = std::getenv("FITFEEL_GNUPLOT"); chosen != nullptr && *chosen != '\0') {
    name = chosen;
  }
  if (name.find('/') != std::string::npos) {
    if (IsExecutableFile(name)) return fs::path(name);
    return std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / name;
    if (IsExecutableFile(candidate)) return candidate;
  }
  return std::nullopt;
}

Gnuplot Gnuplot::Find() {
  auto found = Locate();
  if (!found) {
    throw UnsupportedError(
        "plotting needs gnuplot, which was not found on PATH (or at $FITFEEL_GNUPLOT): install "
        "the Debian package gnuplot-nox (apt-get install gnuplot-nox)");
  }
  return Gnuplot(*found);
}

void Gnuplot::Run(const fs::path& script, const fs::path& work_dir) const {
  const fs::path folder = fs::absolute(work_dir);
  const std::string script_path = fs::absolute(script).string();
  const std::string out_path = (folder / "gnuplot.stdout").string();
  const std::string err_path = (folder / "gnuplot.stderr").string();

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());

  const std::string program = executable_.string();
  // -d: ignore the user's ~/.gnuplot and the system gnuplotrc, so charts look the same for all.
  std::string defaults = "-d";
  std::vector<char*> argv = {const_cast<char*>(program.c_str()), defaults.data(),
                             const_cast<char*>(script_path.c_str()), nullptr};
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    throw std::runtime_error("cannot start gnuplot at '" + program + "': " + ErrnoText(spawned));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      throw std::runtime_error("waiting for gnuplot failed: " + ErrnoText(errno));
    }
  }
  const std::string messages = ReadWholeFile(err_path);
  if (!WIFEXITED(status)) {
    throw std::runtime_error("gnuplot was killed by signal " +
                             std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : -1) +
                             (messages.empty() ? "" : ": " + messages));
  }
  if (WEXITSTATUS(status) != 0 || HasChartMessages(messages)) {
    throw std::runtime_error("gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) +
                             "): " + messages);
  }
}

void InstallAtomically(const fs::path& source, const fs::path& target) {
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string pattern = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = ::mkstemp(buffer.data());
  if (fd < 0) {
    throw UserError("cannot write into '" + folder.string() + "': " + ErrnoText(errno));
  }
  TempFileGuard guard(fd, buffer.data());
  const std::string bytes = ReadWholeFile(source);
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw UserError("cannot write '" + target.string() + "': " + ErrnoText(errno));
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp creates 0600; an image is meant to be shared like any other output file.
  if (::fchmod(fd, 0644) != 0 || guard.CloseFd() != 0) {
    throw UserError("cannot write '" + target.string() + "': " + ErrnoText(errno));
  }
  if (::rename(buffer.data(), target.c_str()) != 0) {
    throw UserError("cannot replace '" + target.string() + "': " + ErrnoText(errno));
  }
  guard.Release();
}

}  // namespace fitfeel::plot
