#include "framework/runtime/bounded_root.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// A wall at w (m) of stiffness k (N/m) with a free stretch before it: the shape of a part sinking
// onto a bore under a load (eq. 9's spring beyond the assembly space), minus the load.
struct Wall {
  double w, k, load;
  double operator()(double s) const { return (s > w ? k * (s - w) : 0.0) - load; }
};

TEST(FindRootNear, AWarmStartOnALinearPieceTakesThreeEvaluations) {
  const Wall wall{-1e-6, 3.7e9, 2.0};  // steel press-fit stiffness, the root 0.54 pm past 0
  const RootSearch r = FindRootNear(wall, 1e-6 * 2.0, 16);
  EXPECT_TRUE(r.found);
  EXPECT_LE(r.evaluations, 3);
  EXPECT_NEAR(wall(r.solution), 0.0, 1e-5);
}

TEST(FindRootNear, AtTheRootTakesOneEvaluation) {
  const Wall wall{-1e-6, 1e6, 1.0};
  const RootSearch r = FindRootNear(wall, 1e-6, 16);
  EXPECT_TRUE(r.found);
  EXPECT_EQ(r.evaluations, 1);
  EXPECT_EQ(r.solution, 0.0);
}

TEST(FindRootNear, CrossesAFreeStretchByWideningTheSearch) {
  for (double w : {2e-6, 30e-6, 400e-6, -250e-6}) {
    const Wall wall{w, 1e8, 0.5};
    // Residual nondecreasing: from a wall on the negative side the root lies below 0.
    const RootSearch r = FindRootNear(wall, 1e-9, 16);
    EXPECT_TRUE(r.found) << w;
    EXPECT_NEAR(r.solution, w + 0.5 / 1e8, 1e-12) << w;
    EXPECT_LE(r.evaluations, 16) << w;
  }
}

TEST(FindRootNear, NothingWithinReachIsNotFound) {
  const Wall wall{2e-3, 1e8, 0.5};
  const RootSearch r = FindRootNear(wall, 1e-9, 16);
  EXPECT_FALSE(r.found);
  EXPECT_LE(r.evaluations, 16);
}

// Whatever the residual, the budget holds; where the search bracketed the root but ran out, the
// point it returns is the best it saw. Random monotone piecewise-linear and smooth residuals.
TEST(FindRootNear, NeverExceedsItsBudgetAndReturnsItsBestPoint) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double w = (u(rng) - 0.5) * 200e-6;
    const double k1 = std::pow(10.0, 3.0 + 7.0 * u(rng)), k2 = k1 * (1.0 + 50.0 * u(rng));
    const double kink = w + 20e-6 * u(rng);
    const double load = 10.0 * u(rng) + 1e-3;
    auto residual = [&](double s) {
      double f = 0.0;
      if (s > w) f += k1 * (std::min(s, kink) - w);
      if (s > kink) f += k2 * (s - kink);
      return f + (trial % 2 ? 1e-9 * std::tanh(s / 1e-6) : 0.0) - load;
    };
    const int budget = 2 + trial % 15;
    const RootSearch r = FindRootNear(residual, 1e-6 * load, budget);
    EXPECT_LE(r.evaluations, budget);
    EXPECT_EQ(r.residual, residual(r.solution));
  }
}

TEST(FindRootNear, ConvergesOnAKinkedResidualWithinSixteenEvaluations) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int worst = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double w = (u(rng) - 0.5) * 20e-6;
    const double k1 = 1e9, k2 = 4e9;
    const double kink = w + 1e-6 * u(rng);
    const double load = 1.0;
    auto residual = [&](double s) {
      double f = 0.0;
      if (s > w) f += k1 * (std::min(s, kink) - w);
      if (s > kink) f += k2 * (s - kink);
      return f - load;
    };
    const RootSearch r = FindRootNear(residual, 1e-6 * load, 16);
    EXPECT_TRUE(r.found);
    EXPECT_NEAR(residual(r.solution), 0.0, 1e-6 * load + 4e9 * 1e-12);
    worst = std::max(worst, r.evaluations);
  }
  RecordProperty("worst_evaluations", worst);
}

}  // namespace
}  // namespace fitfeel
