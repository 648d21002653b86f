#include "framework/safety/force_limiter.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

TEST(ForceLimiter, PassesForcesWithinThePeakAndKeepsDirection) {
  ForceLimiter limiter;
  limiter.Configure(7.9, 1.75, 10.0);
  ForceLimiter::Flags flags;
  const Eigen::Vector3d f(1.0, -2.0, 0.5);
  EXPECT_EQ(limiter.Apply(f, 1e-3, &flags), f);
  EXPECT_FALSE(flags.peak);
  EXPECT_FALSE(flags.continuous);
}

TEST(ForceLimiter, SaturatesAtThePeakKeepingDirection) {
  ForceLimiter limiter;
  limiter.Configure(7.9, 1.75, 10.0);
  ForceLimiter::Flags flags;
  const Eigen::Vector3d f(300.0, -400.0, 0.0);  // 500 N
  const Eigen::Vector3d out = limiter.Apply(f, 1e-3, &flags);
  EXPECT_TRUE(flags.peak);
  EXPECT_LE(out.norm(), 7.9);
  EXPECT_NEAR(out.norm(), 7.9, 1e-9);
  EXPECT_NEAR(out.normalized().dot(f.normalized()), 1.0, 1e-12);
}

TEST(ForceLimiter, SustainedForceConvergesToTheContinuousRating) {
  // A constant 5 N request: the thermal average approaches the continuous rating from below
  // and the delivered force settles at it (1.75 N) within a few windows.
  ForceLimiter limiter;
  const double window = 0.5;
  limiter.Configure(7.9, 1.75, window);
  const Eigen::Vector3d f(0.0, -5.0, 0.0);
  Eigen::Vector3d out;
  bool limited = false;
  for (int i = 0; i < 5000; ++i) {  // 5 s = 10 windows
    ForceLimiter::Flags flags;
    out = limiter.Apply(f, 1e-3, &flags);
    limited = limited || flags.continuous;
    ASSERT_LE(limiter.thermal_rms(), 1.75 * (1.0 + 1e-9));
  }
  EXPECT_TRUE(limited);
  EXPECT_NEAR(out.norm(), 1.75, 1e-3);
  // The first ticks passed the full 5 N: bursts above the continuous rating are allowed.
  ForceLimiter fresh;
  fresh.Configure(7.9, 1.75, window);
  EXPECT_NEAR(fresh.Apply(f, 1e-3, nullptr).norm(), 5.0, 1e-12);
}

TEST(ForceLimiter, NeverExceedsThePeakForRandomRequests) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    std::lognormal_distribution<double> magnitude(0.0, 3.0);
    std::normal_distribution<double> component(0.0, 1.0);
    ForceLimiter limiter;
    limiter.Configure(3.3, 0.88, 1.0);
    for (int i = 0; i < 2000; ++i) {
      Eigen::Vector3d f(component(rng), component(rng), component(rng));
      f *= magnitude(rng);
      const Eigen::Vector3d out = limiter.Apply(f, 1e-3, nullptr);
      ASSERT_LE(out.norm(), 3.3) << "seed " << seed << " tick " << i;
      ASSERT_LE(out.norm(), f.norm() * (1.0 + 1e-15));
      ASSERT_LE(limiter.thermal_rms(), 0.88 * (1.0 + 1e-9));
    }
  }
}

}  // namespace
}  // namespace fitfeel
