// Every file error carries the operating system's reason: a symlink loop is a loop, an unreadable
// file says "permission denied", never a guess such as "does not exist".
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/cli/test/child_process.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;
using test_support::CliResult;
using test_support::ReadText;
using test_support::RunFitfeel;
using test_support::ShellWords;
using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kLoop = "too many levels of symbolic links";

class FileErrorsTest : public ::testing::Test {
 protected:
  FileErrorsTest()
      : dir_(test_support::EmptyTestFolder("file-errors")) {}
  ~FileErrorsTest() override { fs::remove_all(dir_); }

  // The shipped default scenario with its shaft measured from `file` (relative to the scenario).
  fs::path ScenarioMeasuring(const std::string& file) const {
    std::string text = ReadText(test_support::ShippedScenario("paper-case1-h7js6.yaml"));
    const std::size_t bushing = text.find("\n  bushing:");
    EXPECT_NE(bushing, std::string::npos);
    text.insert(bushing, "\n    measured: {roundness: " + file + "}");
    const fs::path scenario = dir_ / "measured.yaml";
    std::ofstream(scenario) << text;
    return scenario;
  }

  fs::path Loop(const std::string& name) const {
    fs::create_symlink(name, dir_ / name);
    return dir_ / name;
  }

  fs::path dir_;
};

TEST_F(FileErrorsTest, AMeasuredPartFileThatIsASymlinkLoopIsALoop) {
  Loop("loop.csv");
  const CliResult r = RunFitfeel(ShellWords({"validate", ScenarioMeasuring("loop.csv").string()}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("parts.shaft.measured.roundness: expected a readable roundness "
                               "measurement file (CSV), found '" +
                               (dir_ / "loop.csv").string() + "', which cannot be opened: " +
                               kLoop));
  EXPECT_THAT(r.err, Not(HasSubstr("does not exist")));
}

TEST_F(FileErrorsTest, AScenarioFileThatIsASymlinkLoopIsALoop) {
  const CliResult r = RunFitfeel(ShellWords({"validate", Loop("loop.yaml").string()}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  // The scenario reader quotes strerror as it is ("Too many ...").
  EXPECT_THAT(r.err, HasSubstr("none that can be opened (Too many levels of symbolic links)"));
}

TEST_F(FileErrorsTest, AnOutputFolderThatIsASymlinkLoopIsALoop) {
  const fs::path loop = Loop("out");
  const CliResult r = RunFitfeel(ShellWords(
      {"run", test_support::ShippedScenario("paper-case1-h7js6.yaml").string(), "--out",
       loop.string()}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("fitfeel: error: run: --out: expected a path to write, found '" +
                               loop.string() + "', which cannot be opened: " + kLoop + "\n"));
}

TEST_F(FileErrorsTest, ARunFolderThatIsASymlinkLoopIsALoop) {
  const fs::path loop = Loop("run");
  const CliResult r = RunFitfeel(
      ShellWords({"plot", "trace", loop.string(), "-o", (dir_ / "trace.png").string()}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("run folder '" + loop.string() + "' cannot be opened: " + kLoop));
}

TEST_F(FileErrorsTest, AMeasuredPartFileNoOneMayReadSaysPermissionDenied) {
  const fs::path file = dir_ / "secret.csv";
  std::ofstream(file) << "height [mm], angle [deg], radius [mm]\n0, 0, 10\n";
  fs::permissions(file, fs::perms::none);
  // Root reads any file (CAP_DAC_OVERRIDE): the CLI runs without that capability, as anyone.
  const test_support::ChildProcess child = test_support::StartChild(
      test_support::FitfeelBinary(), {"validate", ScenarioMeasuring("secret.csv").string()},
      dir_ / "validate.out", dir_ / "validate.err", /*without_read_override=*/::geteuid() == 0);
  const int status = test_support::WaitForChild(child);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 77) {
    GTEST_SKIP() << "running as root without CAP_SETPCAP: the capability that lets root read "
                    "every file cannot be dropped, so no file is unreadable here";
  }
  const std::string err = ReadText(child.err);
  EXPECT_EQ(WEXITSTATUS(status), 2) << err;
  EXPECT_THAT(err, HasSubstr("found '" + file.string() + "', which cannot be opened: permission "
                             "denied"));
}

}  // namespace
}  // namespace fitfeel
