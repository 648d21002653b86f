#include "framework/core/path_check.h"

#include <linux/capability.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

class PathCheckTest : public ::testing::Test {
 protected:
  PathCheckTest()
      : dir_(test_support::EmptyTestFolder("path-check")) {}
  ~PathCheckTest() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(PathCheckTest, AReadableFileAndAFolderPass) {
  std::ofstream(dir_ / "a.csv") << "x";
  EXPECT_EQ(WhyNotReadableFile(dir_ / "a.csv"), "");
  EXPECT_EQ(WhyNotFolder(dir_), "");
}

TEST_F(PathCheckTest, SaysWhatIsThereInstead) {
  std::ofstream(dir_ / "a.csv") << "x";
  EXPECT_EQ(WhyNotReadableFile(dir_ / "absent.csv"), "does not exist");
  EXPECT_EQ(WhyNotReadableFile(dir_), "is a folder");
  EXPECT_EQ(WhyNotReadableFile("/dev/null"), "is not a regular file (a device, pipe or socket)");
  EXPECT_EQ(WhyNotFolder(dir_ / "absent"), "does not exist");
  EXPECT_EQ(WhyNotFolder(dir_ / "a.csv"), "is not a folder");
}

TEST_F(PathCheckTest, ASymlinkLoopIsALoop) {
  fs::create_symlink("loop.csv", dir_ / "loop.csv");
  EXPECT_EQ(WhyNotReadableFile(dir_ / "loop.csv"),
            "cannot be opened: too many levels of symbolic links");
  EXPECT_EQ(WhyNotFolder(dir_ / "loop.csv"), "cannot be opened: too many levels of symbolic links");
}

// What `check` returns in a process without the capabilities that let root read any file, or
// nullopt when they cannot be dropped. Run in a child: the test process keeps its own.
std::optional<std::string> WithoutReadOverride(const fs::path& file) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return std::nullopt;
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2] = {};
    if (::syscall(SYS_capget, &header, data) != 0) ::_exit(77);
    for (const int cap : {CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH}) {
      data[0].effective &= ~(1u << cap);
    }
    if (::syscall(SYS_capset, &header, data) != 0) ::_exit(77);
    const std::string why = WhyNotReadableFile(file);
    const ssize_t written = ::write(pipe_fds[1], why.data(), why.size());
    ::_exit(written == static_cast<ssize_t>(why.size()) ? 0 : 1);
  }
  ::close(pipe_fds[1]);
  std::string text;
  char buffer[256];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, n);
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  return text;
}

TEST_F(PathCheckTest, AFileNoOneMayReadSaysPermissionDenied) {
  const fs::path file = dir_ / "secret.csv";
  std::ofstream(file) << "x";
  fs::permissions(file, fs::perms::none);
  const std::optional<std::string> why =
      ::geteuid() == 0 ? WithoutReadOverride(file) : std::optional(WhyNotReadableFile(file));
  if (!why) GTEST_SKIP() << "root here cannot drop CAP_DAC_OVERRIDE: every file is readable";
  EXPECT_EQ(*why, "cannot be opened: permission denied");
}

}  // namespace
}  // namespace fitfeel
