#include "framework/core/interrupt.h"

#include <unistd.h>

#include <csignal>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

extern "C" void CountingHandler(int) {}

// The disposition of `signal` now.
struct sigaction Current(int signal) {
  struct sigaction action {};
  sigaction(signal, nullptr, &action);
  return action;
}

TEST(InterruptTest, CooperativeSignalIsRecordedAndTheProcessGoesOn) {
  {
    InterruptScope scope("fitfeel test");
    scope.Cooperate();
    EXPECT_FALSE(InterruptFlag().load());
    EXPECT_EQ(InterruptSignal(), 0);
    ASSERT_EQ(std::raise(SIGTERM), 0);
    EXPECT_TRUE(InterruptFlag().load());
    EXPECT_EQ(InterruptSignal(), SIGTERM);
  }
  // Still readable after the scope, for the report; a new scope starts clean.
  EXPECT_EQ(InterruptSignal(), SIGTERM);
  InterruptScope again("fitfeel test");
  EXPECT_FALSE(InterruptFlag().load());
  EXPECT_EQ(InterruptSignal(), 0);
}

TEST(InterruptTest, RestoresTheDispositionsItFound) {
  struct sigaction mine {};
  mine.sa_handler = CountingHandler;
  sigemptyset(&mine.sa_mask);
  struct sigaction saved_int {}, saved_term {};
  sigaction(SIGINT, &mine, &saved_int);
  sigaction(SIGTERM, &mine, &saved_term);
  {
    InterruptScope scope("fitfeel test");
    EXPECT_NE(Current(SIGINT).sa_handler, CountingHandler);
    EXPECT_NE(Current(SIGTERM).sa_handler, CountingHandler);
  }
  EXPECT_EQ(Current(SIGINT).sa_handler, CountingHandler);
  EXPECT_EQ(Current(SIGTERM).sa_handler, CountingHandler);
  sigaction(SIGINT, &saved_int, nullptr);
  sigaction(SIGTERM, &saved_term, nullptr);
}

TEST(InterruptTest, AnIgnoredSignalStaysIgnored) {
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  struct sigaction saved {};
  sigaction(SIGINT, &ignore, &saved);
  {
    InterruptScope scope("fitfeel test");
    scope.Cooperate();
    EXPECT_EQ(Current(SIGINT).sa_handler, SIG_IGN);
    ASSERT_EQ(std::raise(SIGINT), 0);
    EXPECT_EQ(InterruptSignal(), 0);
  }
  sigaction(SIGINT, &saved, nullptr);
}

TEST(InterruptDeathTest, BeforeCooperatingASignalEndsTheProcessWithItsLineAndCode) {
  EXPECT_EXIT(
      {
        InterruptScope scope("fitfeel test");
        std::raise(SIGINT);
      },
      ::testing::ExitedWithCode(130), "^fitfeel test: interrupted by SIGINT; no outputs written\n$");
  EXPECT_EXIT(
      {
        InterruptScope scope("fitfeel test", "stopped serving");
        std::raise(SIGTERM);
      },
      ::testing::ExitedWithCode(143), "^fitfeel test: interrupted by SIGTERM; stopped serving\n$");
}

TEST(InterruptDeathTest, ASecondSignalTakesTheDefaultAction) {
  EXPECT_EXIT(
      {
        InterruptScope scope("fitfeel test");
        scope.Cooperate();
        std::raise(SIGINT);  // recorded
        std::raise(SIGINT);  // insisted: killed by it
        ::_exit(0);
      },
      ::testing::KilledBySignal(SIGINT), "");
}

TEST(InterruptTest, NamesTheSignalsAndTheirExitCodes) {
  EXPECT_EQ(SignalName(SIGINT), "SIGINT");
  EXPECT_EQ(SignalName(SIGTERM), "SIGTERM");
  EXPECT_EQ(InterruptExitCode(SIGINT), 130);
  EXPECT_EQ(InterruptExitCode(SIGTERM), 143);
}

}  // namespace
}  // namespace fitfeel
