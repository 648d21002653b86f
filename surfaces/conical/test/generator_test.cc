// Form evaluation against the oracles of docs/oracles.md ("Form tolerance evaluation") on a
// cone's grid, and the generator's properties over many seeds.
#include <cmath>

#include <gtest/gtest.h>

#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/conical_form.h"
#include "surfaces/conical/conical_generator.h"
#include "surfaces/conical/test/test_parts.h"

namespace fitfeel::conical {
namespace {

SurfaceGrid Grid(const PartSpec& part, Resolution r = Resolution{21, 72}) {
  return ConicalDiscretizer().Discretize(part, r);
}

TEST(ConeForm, LobedSectionsHaveRoundnessTwiceTheAmplitude) {
  const PartSpec pin = test::Pin();
  const SurfaceGrid grid = Grid(pin);
  for (int k : {2, 3, 4, 6}) {  // peaks and troughs on the 5 deg samples
    Eigen::VectorXd v(grid.size());
    for (int i = 0; i < grid.rows; ++i) {
      for (int j = 0; j < grid.columns; ++j) {
        const double beta = grid.column_angle(j);
        // peaks on sample points(to e^2/2R = 0.5 nm here).
        v(grid.index(i, j)) = 3e-6 * std::cos(k * beta) + 2e-6 * std::cos(beta - 1.0);
      }
    }
    EXPECT_NEAR(EvaluateConeForm(FormCharacteristic::kRoundness, GeometryOf(pin), grid, v), 6e-6,
                1e-9)
        << k;
  }
}

TEST(ConeForm, BowedAxisHasStraightnessOfItsSag) {
  const PartSpec pin = test::Pin();
  const SurfaceGrid grid = Grid(pin);
  const double L = GeometryOf(pin).length(), sag = 5e-6;
  Eigen::VectorXd v(grid.size());
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < grid.rows; ++i) {
    const double y = grid.row_position(i);
    const double e = sag * 4.0 * y * (L - y) / (L * L);  // parabolic bow, sag at mid length
    lo = std::min(lo, e);
    hi = std::max(hi, e);
    for (int j = 0; j < grid.columns; ++j) {
      v(grid.index(i, j)) = e * std::cos(grid.column_angle(j) - 0.7);
    }
  }
  // Sampled at row centres the bow spans hi - lo, not quite the sag of the continuous curve.
  EXPECT_NEAR(EvaluateConeForm(FormCharacteristic::kAxisStraightness, GeometryOf(pin), grid, v),
              hi - lo, 2e-9);
}

TEST(ConeForm, ParabolicGeneratrixHasStraightnessAQuarterOfAL2) {
  const PartSpec hole = test::Hole();
  const SurfaceGrid grid = Grid(hole, Resolution{41, 8});
  // a x^2 over [x0, x0 + L] with any tilt: width a L^2 / 4 over the sampled span.
  const double a = 0.02;  // 1/m: 2 um over 20 mm
  Eigen::VectorXd v(grid.size());
  for (int i = 0; i < grid.rows; ++i) {
    const double x = grid.row_position(i) - 0.5 * GeometryOf(hole).length();
    for (int j = 0; j < grid.columns; ++j) v(grid.index(i, j)) = a * x * x + 1e-4 * x;
  }
  const double span = grid.row_position(grid.rows - 1) - grid.row_position(0);
  EXPECT_NEAR(
      EvaluateConeForm(FormCharacteristic::kGeneratrixStraightness, GeometryOf(hole), grid, v),
      a * span * span / 4.0, 1e-12);
}

TEST(ConeGenerator, EveryCharacteristicAloneIsMetAndUsed) {
  // Each tolerance alone, over many seeds: never exceeded, and on average a fair share of it is
  // used (a generator that returned zero form would pass the first check alone).
  for (FormCharacteristic c :
       {FormCharacteristic::kRoundness, FormCharacteristic::kAxisStraightness,
        FormCharacteristic::kGeneratrixStraightness}) {
    PartSpec pin = test::Pin();
    pin.size.lower_deviation = -58e-6;  // h10
    pin.form.tolerance[c] = 5e-6;
    const SurfaceGrid grid = Grid(pin, Resolution{20, 36});
    double sum = 0.0;
    constexpr int kSeeds = 40;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      Rng rng(seed);
      const SkinModelShape sms =
          ConicalVariationGenerator().Generate(pin, grid, TextureMode::kExpected, rng);
      const double value = EvaluateConeForm(c, GeometryOf(pin), grid, sms.form_part);
      EXPECT_LE(value, 5e-6 + 1e-12) << ToString(c) << " seed " << seed;
      sum += value;
      const TwoPointRange size = TwoPointSizes(grid, sms.variation);
      EXPECT_GE(size.min, -58e-6 - 1e-12);
      EXPECT_LE(size.max, 1e-12);
    }
    EXPECT_GT(sum / kSeeds, 0.2 * 5e-6) << ToString(c);
  }
}

TEST(ConeGenerator, ActualSizesSpreadOverTheToleranceZone) {
  PartSpec pin = test::Pin();
  pin.size.lower_deviation = -58e-6;
  const SurfaceGrid grid = Grid(pin, Resolution{8, 8});
  double lo = 1.0, hi = -1.0;
  for (int seed = 1; seed <= 200; ++seed) {
    Rng rng(seed);
    const SkinModelShape sms =
        ConicalVariationGenerator().Generate(pin, grid, TextureMode::kExpected, rng);
    const double d = 2.0 * sms.dimension_part(0);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  EXPECT_LT(lo, -0.9 * 58e-6);
  EXPECT_GT(hi, -0.1 * 58e-6);
}

TEST(ConeGenerator, SampledTextureStaysInItsRange) {
  PartSpec pin = test::Pin();
  pin.size.lower_deviation = -58e-6;
  pin.texture.rz = 3.2e-6;
  pin.texture.ra = 0.8e-6;
  const SurfaceGrid grid = Grid(pin, Resolution{20, 36});
  Rng rng(3);
  const SkinModelShape sms =
      ConicalVariationGenerator().Generate(pin, grid, TextureMode::kSampled, rng);
  EXPECT_LE(sms.surface_part.cwiseAbs().maxCoeff(), 1.6e-6);
  EXPECT_GT(sms.surface_part.cwiseAbs().maxCoeff(), 0.0);
  // sigma = range / 3 = 0.533 um; sample standard deviation of 720 draws within 15 %.
  const double sd = std::sqrt(sms.surface_part.squaredNorm() / sms.surface_part.size());
  EXPECT_NEAR(sd, 1.6e-6 / 3.0 * 0.986, 0.15 * 1.6e-6 / 3.0);
}

}  // namespace
}  // namespace fitfeel::conical
