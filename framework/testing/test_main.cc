// The main of every GoogleTest executable: each test process gets a temporary folder of its own.
//
// ctest runs each test case as its own process, several at once, and two suites may share one
// machine. A fixed name under the system's temporary folder is then shared by processes that
// each think they own it (one removes and recreates a folder another is writing into). Here the
// process makes a fresh folder (mkdtemp) and points TMPDIR and TEST_TMPDIR at it before any test
// runs, so ::testing::TempDir(), std::filesystem::temp_directory_path() and every child process
// (the CLI that tests start) write only there. The folder is removed when every test passed and
// kept, with its path printed, when one failed.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace {

std::string MakePrivateTempFolder() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = (base != nullptr && base[0] != '\0') ? base : "/tmp";
  pattern += "/fitfeel-test-XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (::mkdtemp(name.data()) == nullptr) {
    std::perror(("fitfeel test main: mkdtemp " + pattern).c_str());
    std::exit(2);
  }
  return name.data();
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const std::string folder = MakePrivateTempFolder();
  ::setenv("TMPDIR", folder.c_str(), 1);
  ::setenv("TEST_TMPDIR", folder.c_str(), 1);
  const int status = RUN_ALL_TESTS();
  if (status == 0 && std::getenv("FITFEEL_KEEP_TEST_TMP") == nullptr) {
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
  } else {
    std::fprintf(stderr, "fitfeel test main: this process's temporary folder is kept: %s\n",
                 folder.c_str());
  }
  return status;
}
