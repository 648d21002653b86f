#include "framework/model/texture_contact.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// docs/oracles.md, N(0,1) truncated to [-3, 3].
struct Row {
  double g, exceed, first, second;
};
constexpr Row kOracle[] = {{-1.0, 0.842269, 1.080451, 1.904944},
                           {0.0, 0.5, 0.395578, 0.486668},
                           {1.0, 0.157731, 0.080451, 0.068393},
                           {2.0, 0.021458, 0.006777, 0.003460}};

TEST(TruncatedGaussian, MatchesOracleTable) {
  const TruncatedGaussian x{0.0, 1.0, -3.0, 3.0};
  for (const Row& r : kOracle) {
    EXPECT_NEAR(ExceedanceProbability(x, r.g), r.exceed, 1e-6) << "g=" << r.g;
    EXPECT_NEAR(ExpectedInterference(x, r.g), r.first, 1e-6) << "g=" << r.g;
    EXPECT_NEAR(ExpectedSquaredInterference(x, r.g), r.second, 1e-6) << "g=" << r.g;
  }
}

TEST(TruncatedGaussian, LimitsAndContinuity) {
  const TruncatedGaussian x{0.3, 0.7, -1.2, 2.5};
  EXPECT_EQ(ExpectedInterference(x, 2.5), 0.0);
  EXPECT_EQ(ExpectedInterference(x, 9.0), 0.0);
  EXPECT_NEAR(ExpectedInterference(x, 2.5 - 1e-9), 0.0, 1e-12);
  // Continuous across the lower limit; linear with slope -1 below it.
  EXPECT_NEAR(ExpectedInterference(x, -1.2 - 1e-9), ExpectedInterference(x, -1.2 + 1e-9), 1e-8);
  EXPECT_NEAR(ExpectedInterference(x, -3.0) - ExpectedInterference(x, -2.0), 1.0, 1e-12);
  EXPECT_NEAR(ExpectedSquaredInterference(x, -1.2 - 1e-9),
              ExpectedSquaredInterference(x, -1.2 + 1e-9), 1e-8);
  EXPECT_THROW(ExpectedInterference(TruncatedGaussian{0.0, 0.0, -1.0, 1.0}, 0.0),
               std::invalid_argument);
}

// Independent check by sampling (rejection from the seeded normal) for an asymmetric case.
TEST(TruncatedGaussian, AgreesWithSampling) {
  const TruncatedGaussian x{0.4, 1.3, -1.0, 3.0};
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(x.mean, x.sigma);
  const double gaps[] = {-2.0, -0.5, 0.4, 1.7};
  double sum1[4] = {}, sum2[4] = {}, count = 0;
  while (count < 400000) {
    const double v = normal(rng);
    if (v < x.lower || v > x.upper) continue;
    ++count;
    for (int k = 0; k < 4; ++k) {
      const double d = std::max(0.0, v - gaps[k]);
      sum1[k] += d;
      sum2[k] += d * d;
    }
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(sum1[k] / count, ExpectedInterference(x, gaps[k]), 5e-3) << gaps[k];
    EXPECT_NEAR(sum2[k] / count, ExpectedSquaredInterference(x, gaps[k]), 1e-2) << gaps[k];
  }
}

TEST(TruncatedGaussian, PaperTextureLimits) {
  // Paper Table 2: A = 3.2 um, Rz = 1.6 um on both parts.
  const TextureSpec t{3.2e-6, 0.4e-6, 1.6e-6};
  const TruncatedGaussian one = SurfaceTexture(t);
  EXPECT_DOUBLE_EQ(one.upper, 2.4e-6);
  EXPECT_DOUBLE_EQ(one.sigma, 0.8e-6);
  const TruncatedGaussian eq = EquivalentTexture(t, t);
  EXPECT_DOUBLE_EQ(eq.upper, 4.8e-6);  // A + Rz
  EXPECT_DOUBLE_EQ(eq.lower, -4.8e-6);
  EXPECT_NEAR(eq.sigma, std::sqrt(2.0) * 0.8e-6, 1e-18);
  EXPECT_EQ(EquivalentTexture(TextureSpec{}, TextureSpec{}).sigma, 0.0);
}

TEST(ExpectedInterferenceTable, InterpolatesTheClosedForm) {
  const TruncatedGaussian x = EquivalentTexture({3.2e-6, 0.4e-6, 1.6e-6}, {3.2e-6, 0.4e-6, 1.6e-6});
  const ExpectedInterferenceTable table(x);
  ASSERT_FALSE(table.sharp());
  for (double g = -8e-6; g <= 8e-6; g += 0.0137e-6) {
    EXPECT_NEAR(table(g), ExpectedInterference(x, g), 1e-6 * x.sigma) << g;
  }
  const ExpectedInterferenceTable sharp;
  EXPECT_EQ(sharp(-2e-6), 2e-6);
  EXPECT_EQ(sharp(1e-6), 0.0);
}

}  // namespace
}  // namespace fitfeel
