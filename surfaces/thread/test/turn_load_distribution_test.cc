// Sopwith's load over the engaged turns: shares sum to one, fall away from the bearing face,
// are uniform without shear lag, and match a hand value.
#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/turn_load_distribution.h"

namespace fitfeel::thread {
namespace {

TEST(TurnLoadDistributionTest, HandValueForTwoTurns) {
  // L = 2 P, lambda L = 1: share_0 = (sinh 1 - sinh 0.5) / sinh 1 = (1.175201 - 0.521095)
  // / 1.175201 = 0.556591, share_1 = sinh 0.5 / sinh 1 = 0.443409.
  const std::vector<double> shares = TurnLoadShares(3e-3, 1.5e-3, 1.0 / 3e-3);
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_NEAR(shares[0], 0.556591, 1e-6);
  EXPECT_NEAR(shares[1], 0.443409, 1e-6);
}

TEST(TurnLoadDistributionTest, SharesSumToOneAndFallFromTheBearingFace) {
  for (double lambda_l : {1e-3, 0.5, 2.0, 8.0, 40.0, 2000.0}) {
    for (double length : {8.4e-3, 9e-3, 15e-3}) {  // M10 nut height; whole and partial turns
      const std::vector<double> shares = TurnLoadShares(length, 1.5e-3, lambda_l / length);
      EXPECT_EQ(shares.size(), static_cast<std::size_t>(std::ceil(length / 1.5e-3 - 1e-6)));
      EXPECT_NEAR(std::accumulate(shares.begin(), shares.end(), 0.0), 1.0, 1e-12) << lambda_l;
      for (std::size_t i = 1; i < shares.size(); ++i) {
        // At lambda L = 2000 the far turns' shares underflow to zero.
        EXPECT_TRUE(shares[i] < shares[i - 1] || shares[i] == 0.0) << lambda_l << " turn " << i;
        EXPECT_GE(shares[i], 0.0);
      }
    }
  }
  // Strong shear lag: the first turn takes 1 - exp(-lambda P) of the load.
  const std::vector<double> steep = TurnLoadShares(15e-3, 1.5e-3, 2000.0 / 15e-3);
  EXPECT_NEAR(steep[0], 1 - std::exp(-200.0), 1e-12);
}

TEST(TurnLoadDistributionTest, UniformWithoutShearLag) {
  for (double lambda : {0.0, 1e-9}) {
    const std::vector<double> shares = TurnLoadShares(15e-3, 1.5e-3, lambda);
    ASSERT_EQ(shares.size(), 10u);
    for (double s : shares) EXPECT_NEAR(s, 0.1, 1e-9);
  }
  // 8.4 mm on 1.5 mm: five whole turns and 0.6 of a sixth.
  const std::vector<double> partial = TurnLoadShares(8.4e-3, 1.5e-3, 0.0);
  ASSERT_EQ(partial.size(), 6u);
  EXPECT_NEAR(partial[0], 1.5 / 8.4, 1e-12);
  EXPECT_NEAR(partial[5], 0.9 / 8.4, 1e-12);
}

TEST(TurnLoadDistributionTest, DecayRateAndRefusals) {
  // k' = 1e12 Pa, E A = 1e8 N for both: lambda = sqrt(1e12 * 2e-8) = 141.421 1/m.
  EXPECT_NEAR(SopwithDecayRate(1e12, 1e8, 1e8), 141.421356, 1e-6);
  EXPECT_THROW(SopwithDecayRate(0.0, 1e8, 1e8), UserError);
  EXPECT_THROW(SopwithDecayRate(1e12, std::nan(""), 1e8), UserError);
  EXPECT_THROW(TurnLoadShares(15e-3, 0.0, 100.0), UserError);
  EXPECT_THROW(TurnLoadShares(-1e-3, 1.5e-3, 100.0), UserError);
  EXPECT_THROW(TurnLoadShares(15e-3, 1.5e-3, -1.0), UserError);
  EXPECT_THROW(TurnLoadShares(15e-3, 1.5e-3, INFINITY), UserError);
  EXPECT_THROW(TurnLoadShares(1.0, 1e-6, 1.0), UserError);
}

}  // namespace
}  // namespace fitfeel::thread
