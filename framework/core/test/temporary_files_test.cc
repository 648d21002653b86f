#include "framework/core/temporary_files.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

class TemporaryFilesTest : public ::testing::Test {
 protected:
  TemporaryFilesTest()
      : dir_(test_support::EmptyTestFolder("temporary-files")) {}
  ~TemporaryFilesTest() override { fs::remove_all(dir_); }

  fs::path Touch(const std::string& name) const {
    std::ofstream(dir_ / name) << "x";
    return dir_ / name;
  }

  fs::path dir_;
};

// The number of a process that has ended (forked, exited, reaped): what a killed run leaves.
long DeadProcess() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST_F(TemporaryFilesTest, NamesATemporaryBesideItsFileWithThisProcess) {
  EXPECT_EQ(TemporaryPathFor(dir_ / "trace.csv"),
            dir_ / (".trace.csv.tmp-" + std::to_string(::getpid())));
  EXPECT_EQ(TemporaryPathFor("a.csv"), fs::path(".a.csv.tmp-" + std::to_string(::getpid())));
}

TEST_F(TemporaryFilesTest, RemovesWhatADeadProcessLeftAndNothingElse) {
  const std::string dead = std::to_string(DeadProcess());
  // A process that is running for sure: this test's parent.
  const std::string running = std::to_string(::getppid());
  Touch(".trace.csv.tmp-" + dead);
  Touch(".summary.json.tmp-" + dead);
  Touch(".recording.csv.tmp-" + dead + ".partial");
  Touch(".trace.csv.tmp-" + running);  // another fitfeel writing into the same folder
  Touch("trace.csv");
  Touch(".trace.csv.tmp-12ab");        // not a process number
  Touch(".tmp-" + dead);               // no file name before the marker
  Touch("trace.csv.tmp-" + dead);      // not hidden: not a name of ours
  fs::create_directories(dir_ / (".folder.tmp-" + dead));  // a folder is never ours

  const StaleTemporaries stale = RemoveStaleTemporaries(dir_);
  ASSERT_EQ(stale.removed.size(), 3u);
  EXPECT_EQ(stale.removed[0], dir_ / (".recording.csv.tmp-" + dead + ".partial"));
  EXPECT_EQ(stale.removed[1], dir_ / (".summary.json.tmp-" + dead));
  EXPECT_EQ(stale.removed[2], dir_ / (".trace.csv.tmp-" + dead));
  EXPECT_EQ(stale.processes, std::vector<long>{std::stol(dead)});
  EXPECT_TRUE(stale.failures.empty());
  for (const auto& name : {".trace.csv.tmp-" + running, std::string("trace.csv"),
                           std::string(".trace.csv.tmp-12ab"), ".tmp-" + dead,
                           "trace.csv.tmp-" + dead, ".folder.tmp-" + dead}) {
    EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  }
  for (const auto& name : {".trace.csv.tmp-" + dead, ".summary.json.tmp-" + dead}) {
    EXPECT_FALSE(fs::exists(dir_ / name)) << name;
  }
}

TEST_F(TemporaryFilesTest, ThisProcessNumberIsALeftoverOfAnEarlierProcess) {
  // Called before this process writes into the folder: a temporary with its number was left by a
  // process of the same number long gone (numbers are reused, in containers often).
  const fs::path mine = Touch(".trace.csv.tmp-" + std::to_string(::getpid()));
  const StaleTemporaries stale = RemoveStaleTemporaries(dir_);
  EXPECT_EQ(stale.removed, std::vector<fs::path>{mine});
  EXPECT_FALSE(fs::exists(mine));
}

TEST_F(TemporaryFilesTest, AMissingFolderHoldsNone) {
  const StaleTemporaries stale = RemoveStaleTemporaries(dir_ / "absent");
  EXPECT_TRUE(stale.removed.empty());
  EXPECT_TRUE(stale.failures.empty());
}

}  // namespace
}  // namespace fitfeel
