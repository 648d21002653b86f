// A run asked to stop (RunOptions::stop, the flag an interrupt sets) ends at the next tick
// boundary, leaves no file and says how far it got.
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>

#include "framework/core/interrupt.h"
#include "framework/runtime/run.h"
#include "framework/runtime/test/fake_scene.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/stop_at_tick.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// A folder of this test only, not created.
fs::path TestDir() { return test_support::EmptyTestFolder("interrupted-run") / "out"; }

using test_support::StopAtTick;

TEST(InterruptedRunTest, StopsAtTheNextTickBoundaryAndWritesNothing) {
  const fs::path dir = TestDir();
  std::atomic<bool> stop{false};
  StopAtTick observer(&stop, 10);
  RunOptions options;
  options.out_dir = dir;
  options.stop = &stop;
  options.observer = &observer;
  bool folder_while_running = false;
  options.watch = [&](const Scheduler* scheduler) {
    if (scheduler != nullptr) folder_while_running = fs::exists(dir);
  };
  try {
    RunScene(testing::MakeFakeScene(5, 0.5), options);
    FAIL() << "an interrupted run returned";
  } catch (const Interrupted& e) {
    EXPECT_STREQ(e.what(), "after 10 of 500 ticks; no outputs written");
  }
  EXPECT_TRUE(folder_while_running);  // the run had started writing
  EXPECT_FALSE(fs::exists(dir));      // the folder it created went with its temporaries
}

TEST(InterruptedRunTest, KeepsAFolderItFoundAndLeavesItAsItWas) {
  const fs::path dir = TestDir();
  fs::create_directories(dir);
  std::atomic<bool> stop{false};
  StopAtTick observer(&stop, 3);
  RunOptions options;
  options.out_dir = dir;
  options.stop = &stop;
  options.observer = &observer;
  EXPECT_THROW(RunScene(testing::MakeFakeScene(5, 0.5), options), Interrupted);
  ASSERT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(InterruptedRunTest, AFlagSetWhilePreparingStopsBeforeAnyFileOrTick) {
  const fs::path dir = TestDir();
  std::atomic<bool> stop{false};
  RunOptions options;
  options.out_dir = dir;
  options.stop = &stop;
  bool ticked = false;
  options.watch = [&](const Scheduler*) { ticked = true; };
  // Set by the time Prepare returns, as by a signal during the preparation.
  stop.store(true);
  try {
    RunScene(testing::MakeFakeScene(5, 0.5), options);
    FAIL() << "an interrupted run returned";
  } catch (const Interrupted& e) {
    EXPECT_STREQ(e.what(), "while preparing the scene; no outputs written");
  }
  EXPECT_FALSE(ticked);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(InterruptedRunTest, AnUnsetFlagChangesNothing) {
  const fs::path dir = TestDir();
  std::atomic<bool> stop{false};
  RunOptions options;
  options.out_dir = dir;
  options.stop = &stop;
  const RunResult result = RunScene(testing::MakeFakeScene(5, 0.5), options);
  EXPECT_EQ(result.stats.ticks, 500u);
  EXPECT_TRUE(fs::exists(dir / "trace.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fitfeel
