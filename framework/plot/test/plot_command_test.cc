// Runs the real `fitfeel plot` binary: bad input exits 2 with a clear message on stderr and writes
// no image; good input writes the images it names.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/plot/test/test_support.h"

extern char** environ;

namespace fitfeel::plot {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ScratchDir;

const fs::path kFitfeel = fs::path(FITFEEL_TEST_BUILD_DIR) / "bin" / "fitfeel";

struct Result {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs fitfeel with `args` in `cwd` (no shell), capturing its output.
Result Fitfeel(const std::vector<std::string>& args, const fs::path& cwd) {
  const std::string out = (cwd / ".stdout").string(), err = (cwd / ".stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  std::vector<std::string> all = {kFitfeel.string(), "plot"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  Result result;
  if (posix_spawn(&pid, kFitfeel.c_str(), &actions, nullptr, argv.data(), environ) == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  result.out = testing::ReadFile(out);
  result.err = testing::ReadFile(err);
  fs::remove(out);
  fs::remove(err);
  return result;
}

bool NoImages(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const auto ext = entry.path().extension();
    if (ext == ".png" || ext == ".svg") return false;
  }
  return true;
}

TEST(PlotCommand, MissingRunFolderExitsTwo) {
  ScratchDir dir;
  const Result r = Fitfeel({"trace", "no-such-run", "-o", "chart.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("run folder 'no-such-run' does not exist"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, TraceWithoutNeededColumnsExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);
  testing::WriteFile(dir.path() / "run" / "trace.csv", "t_s,stage,depth_mm\n0,constrained,0\n");
  const Result r = Fitfeel({"trace", "run", "-o", "chart"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("header lacks the column(s) fx_N, fy_N, fz_N"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, UnknownExtensionExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);
  const Result r = Fitfeel({"trace", "run", "-o", "chart.jpeg"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("has the extension '.jpeg'; expected .png, .svg"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, DepthOutsideTheRunExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);  // constrained from 0 to 17.9 mm
  const Result r = Fitfeel({"pressure", "run", "--depth", "18.5", "-o", "p.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("depth 18.5 mm is outside the run's constrained depth range "
                               "0.000 mm to 17.900 mm"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, PressureNeedsTheRunsScenarioFile) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);  // names scenarios/s.yaml
  const Result r = Fitfeel({"pressure", "run", "--depth", "5", "-o", "p.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("scenario file was not found at 'scenarios/s.yaml'"));
}

TEST(PlotCommand, SmsOfAMissingScenarioExitsTwo) {
  ScratchDir dir;
  const Result r = Fitfeel({"sms", "absent.yaml", "-o", "sms.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("absent.yaml"));
  EXPECT_TRUE(NoImages(dir.path()));
}

// The real cylindrical surface and simulated device plugins on the paper's scenario. They are part
// of the build once the cylindrical generator and the runtime have landed; before that this build
// has nothing to load the scenario with.
const fs::path kPlugins = fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins";
bool HaveCase1Plugins() {
  return fs::exists(kPlugins / "libfitfeel_surface_cylindrical.so") &&
         fs::exists(kPlugins / "libfitfeel_device_simulated.so");
}
const fs::path kCase1 = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / "paper-case1-h7js6.yaml";

TEST(PlotCommand, SmsOfThePaperScenarioWritesPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  if (!HaveCase1Plugins()) GTEST_SKIP() << "no cylindrical surface or simulated device plugin";
  ScratchDir dir;
  const Result r = Fitfeel({"sms", kCase1.string(), "-o", "sms"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "sms.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "sms.svg"));
  const Result one =
      Fitfeel({"sms", kCase1.string(), "--part", "shaft", "-o", "shaft.png"}, dir.path());
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "shaft.png"));
  const Result bad = Fitfeel({"sms", kCase1.string(), "--part", "gear", "-o", "g.png"}, dir.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("no part 'gear'"));
}

TEST(PlotCommand, TraceWritesPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteRun(dir.path() / "a", "paper-case1-h7js6", "gps", 12.0);
  testing::WriteRun(dir.path() / "b", "paper-case1-h7g6", "gps", 0.4);
  const Result r = Fitfeel({"trace", "a", "b", "--log", "-o", "trace"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "trace.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "trace.svg"));
  EXPECT_THAT(r.out, HasSubstr("wrote trace.png"));
}

}  // namespace
}  // namespace fitfeel::plot
