// SIGINT and SIGTERM stop `fitfeel run` cleanly; what a SIGKILL leaves is swept by the next run
// into the same folder. The real CLI as a child process: it is started, the test waits until the
// run has started writing (its temporary appears), then signals it.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/cli/test/child_process.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;
using test_support::ChildEnded;
using test_support::ChildProcess;
using test_support::FitfeelBinary;
using test_support::ReadText;
using test_support::StartChild;
using test_support::WaitForChild;
using ::testing::HasSubstr;

// The shipped default scenario with another run section.
std::string ScenarioWithRun(const std::string& duration, const std::string& clock) {
  std::string text = ReadText(test_support::ShippedScenario("paper-case1-h7js6.yaml"));
  text = std::regex_replace(text, std::regex("\n  duration: [^\n]*"), "\n  duration: " + duration);
  text = std::regex_replace(text, std::regex("\n  clock: [^\n]*"), "\n  clock: " + clock);
  return text;
}

// The names of the temporaries in `folder` (".NAME.tmp-PID").
std::vector<std::string> Temporaries(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.find(".tmp-") != std::string::npos) names.push_back(name);
  }
  return names;
}

std::vector<std::string> Entries(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class InterruptCommandTest : public ::testing::Test {
 protected:
  InterruptCommandTest()
      : dir_(test_support::EmptyTestFolder("interrupt")), out_(dir_ / "out") {
    fs::create_directories(out_);
    // Ten minutes on the real clock: the run cannot end before the test signals it, however
    // loaded the machine, and it writes 1 000 rows a second meanwhile.
    std::ofstream(dir_ / "long.yaml") << ScenarioWithRun("600 s", "realtime");
    std::ofstream(dir_ / "short.yaml") << ScenarioWithRun("0.2 s", "virtual");
  }
  ~InterruptCommandTest() override {
    if (run_.pid > 0 && !ended_) {
      ::kill(run_.pid, SIGKILL);
      WaitForChild(run_);
    }
    fs::remove_all(dir_);
  }

  // Starts the long run into out_ and returns once it has started writing: its temporary trace
  // is there. The bound only keeps a broken build from hanging the suite: preparing the scene
  // takes well under a second.
  void StartLongRunAndWaitUntilItWrites() {
    run_ = StartChild(FitfeelBinary(), {"run", (dir_ / "long.yaml").string(), "--out", out_.string()},
                      dir_ / "run.out", dir_ / "run.err");
    ASSERT_GT(run_.pid, 0);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (Temporaries(out_).empty()) {
      int status = 0;
      if (ChildEnded(run_, &status)) {
        ended_ = true;
        FAIL() << "the run ended before writing (status " << status << "): "
               << ReadText(run_.err);
      }
      ASSERT_LT(std::chrono::steady_clock::now(), give_up) << "the run never started writing";
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }

  // Sends `signal` and returns the run's exit status.
  int Signal(int signal) {
    ::kill(run_.pid, signal);
    const int status = WaitForChild(run_);
    ended_ = true;
    return status;
  }

  fs::path dir_;
  fs::path out_;
  ChildProcess run_;
  bool ended_ = false;
};

TEST_F(InterruptCommandTest, SigintStopsTheRunSaysSoAndLeavesNothing) {
  ASSERT_NO_FATAL_FAILURE(StartLongRunAndWaitUntilItWrites());
  const int status = Signal(SIGINT);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_THAT(ReadText(run_.err),
              ::testing::MatchesRegex("fitfeel run: interrupted by SIGINT after [0-9]+ of 600000 "
                                      "ticks; no outputs written\n"));
  // The folder was there before the run: it stays, as empty as it was.
  EXPECT_TRUE(Entries(out_).empty()) << ::testing::PrintToString(Entries(out_));
}

TEST_F(InterruptCommandTest, SigtermStopsTheRunSaysSoAndLeavesNothing) {
  ASSERT_NO_FATAL_FAILURE(StartLongRunAndWaitUntilItWrites());
  const int status = Signal(SIGTERM);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_THAT(ReadText(run_.err),
              ::testing::MatchesRegex("fitfeel run: interrupted by SIGTERM after [0-9]+ of 600000 "
                                      "ticks; no outputs written\n"));
  EXPECT_TRUE(Entries(out_).empty()) << ::testing::PrintToString(Entries(out_));
}

TEST_F(InterruptCommandTest, TheRunAfterASigkillSweepsWhatItLeftAndSaysSo) {
  ASSERT_NO_FATAL_FAILURE(StartLongRunAndWaitUntilItWrites());
  const int status = Signal(SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_EQ(WTERMSIG(status), SIGKILL);
  // Nothing can clean up after a SIGKILL: its temporary is there.
  const std::string left = ".trace.csv.tmp-" + std::to_string(run_.pid);
  ASSERT_EQ(Temporaries(out_), std::vector<std::string>{left});

  const test_support::CliResult next = test_support::RunFitfeel(
      test_support::ShellWords({"run", (dir_ / "short.yaml").string(), "--out", out_.string()}));
  ASSERT_EQ(next.exit_code, 0) << next.err;
  EXPECT_EQ(next.err, "fitfeel: note: removed 1 temporary a killed run (process " +
                          std::to_string(run_.pid) + ") left in '" + out_.string() + "': " + left +
                          "\n");
  EXPECT_EQ(Entries(out_), (std::vector<std::string>{"summary.json", "trace.csv"}));
}

}  // namespace
}  // namespace fitfeel
