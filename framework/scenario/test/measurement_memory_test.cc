// The real `fitfeel validate` on large measurement files: the file is read line by line, so the
// command's peak memory (the child's own ru_maxrss) does not grow with the file's size, and a
// file of more samples than any grid has cells is refused at the first sample over the cap, with
// the whole message, in bounded memory.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/scenario/measurement_file.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"

extern char** environ;

namespace fitfeel::scenario {
namespace {

namespace fs = std::filesystem;
using ::fitfeel::test_support::FitfeelBinary;
using ::fitfeel::test_support::ReadText;
using ::fitfeel::test_support::ShippedScenario;
using ::testing::HasSubstr;

// A folder of this process and test, removed with the fixture (the files are large).
class MeasurementMemory : public ::testing::Test {
 protected:
  MeasurementMemory()
      : dir_(test_support::EmptyTestFolder("measurement-memory")) {}
  ~MeasurementMemory() override { fs::remove_all(dir_); }

  // The paper scene with its shaft measured from the point cloud `points` (in dir_).
  fs::path SceneWith(const std::string& points) const {
    std::string text = ReadText(ShippedScenario("paper-case1-h7js6.yaml"));
    const std::string after = "\n  shaft:\n";
    const std::size_t at = text.find(after);
    EXPECT_NE(at, std::string::npos);
    text.insert(at + after.size(), "    measured: {points: " + points + "}\n");
    const fs::path file = dir_ / (points + ".yaml");
    std::ofstream(file) << text;
    return file;
  }

  // A point cloud of the 20 mm shaft: `samples` points on its nominal cylinder (x, y, z in mm,
  // y along the axis), after `comment_bytes` of comment lines; returns the file's size.
  std::uintmax_t WritePoints(const std::string& name, std::size_t samples,
                             std::size_t comment_bytes) const {
    std::ofstream out(dir_ / name, std::ios::binary);
    const std::string comment = "# " + std::string(97, 'm') + "\n";  // 100 bytes
    for (std::size_t written = 0; written < comment_bytes; written += comment.size()) {
      out << comment;
    }
    out << "x [mm],y [mm],z [mm]\n";
    std::string block;
    char number[32];
    for (std::size_t k = 0; k < samples; ++k) {
      // Around the circle and along the axis: x = 10 cos, z = 10 sin at a few exact angles.
      static const char* const kAround[] = {"10,", "0,", "-10,", "0,"};
      static const char* const kAcross[] = {",0\n", ",10\n", ",0\n", ",-10\n"};
      block += kAround[k % 4];
      const auto end = std::to_chars(number, number + sizeof number,
                                     static_cast<double>(k % 40000) * 1e-3);
      block.append(number, end.ptr);
      block += kAcross[k % 4];
      if (block.size() > (1 << 20)) {
        out << block;
        block.clear();
      }
    }
    out << block;
    out.close();
    return fs::file_size(dir_ / name);
  }

  struct Child {
    int exit_code = -1;
    std::string err;
    long peak_kib = 0;  // the child's own peak resident set (ru_maxrss)
  };

  // `fitfeel validate SCENE`, its peak memory measured by wait4 on that one process.
  Child Validate(const fs::path& scene) const {
    const std::string binary = FitfeelBinary().string();
    const fs::path out = dir_ / "validate.out", err = dir_ / "validate.err";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    std::vector<std::string> words = {binary, "validate", scene.string()};
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    Child child;
    if (spawned != 0) {
      ADD_FAILURE() << "cannot start " << binary;
      return child;
    }
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid) {
      ADD_FAILURE() << "wait4 failed";
      return child;
    }
    if (WIFEXITED(status)) child.exit_code = WEXITSTATUS(status);
    child.err = ReadText(err);
    child.peak_kib = usage.ru_maxrss;
    return child;
  }

  fs::path dir_;
};

// A cloud just over the sample cap (about 70 MB) is refused at the first sample beyond it, the
// message whole, well within 300 MB: the samples kept are the cap's, not the file's.
TEST_F(MeasurementMemory, MoreSamplesThanTheCapAreRefusedAtTheFirstOneBeyond) {
  if (!fs::exists(FitfeelBinary())) GTEST_SKIP() << "build the fitfeel target first";
  WritePoints("dense.csv", kMaxMeasurementSamples + 1000, 0);
  const Child child = Validate(SceneWith("dense.csv"));
  EXPECT_EQ(child.exit_code, 2) << child.err;
  // Line 1 is the header: sample k is on line k + 1.
  const std::string where = (dir_ / "dense.csv").string() + ":" +
                            std::to_string(kMaxMeasurementSamples + 2) + ":1: ";
  EXPECT_THAT(child.err, HasSubstr(where + "parts.shaft.measured.points: expected at most 4000000 "
                                           "samples (the cells of the finest grid a part gets), "
                                           "found a sample beyond them\n"));
  EXPECT_GT(child.peak_kib, 0);
  EXPECT_LT(child.peak_kib, 300 * 1024) << "peak resident set, KiB";
  std::printf("[ measured ] %zu samples refused at a peak of %ld MiB\n",
              kMaxMeasurementSamples + 1000, child.peak_kib / 1024);
}

// The same samples after 20 MB and after 200 MB of comment lines: read, at the same peak memory
// (a reader that held the file would need 180 MB more, and more again for its copies).
TEST_F(MeasurementMemory, PeakMemoryDoesNotGrowWithTheFilesSize) {
  if (!fs::exists(FitfeelBinary())) GTEST_SKIP() << "build the fitfeel target first";
  const std::uintmax_t small = WritePoints("small.csv", 100'000, 20'000'000);
  const std::uintmax_t large = WritePoints("large.csv", 100'000, 200'000'000);
  ASSERT_GT(large, 9 * small);
  const Child a = Validate(SceneWith("small.csv"));
  const Child b = Validate(SceneWith("large.csv"));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_GT(a.peak_kib, 0);
  EXPECT_LT(b.peak_kib, a.peak_kib + 16 * 1024)
      << "peak resident set, KiB: " << a.peak_kib << " for " << small << " bytes, " << b.peak_kib
      << " for " << large << " bytes";
  EXPECT_LT(b.peak_kib, 300 * 1024);
  std::printf("[ measured ] peak %ld MiB for a %ju MB file, %ld MiB for %ju MB\n",
              a.peak_kib / 1024, small / 1000000, b.peak_kib / 1024, large / 1000000);
}

}  // namespace
}  // namespace fitfeel::scenario
