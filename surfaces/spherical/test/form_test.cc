// Sphere form evaluation against closed forms, and the generator's properties over many seeds.
#include <cmath>

#include <gtest/gtest.h>

#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_form.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

TEST(SphereForm, ShiftedCentreIsNoFormAndLobesAreTwiceTheAmplitude) {
  const PartSpec ball = test::Ball();
  const SphericalGeometry& g = GeometryOf(ball);
  const SurfaceGrid grid = SphericalDiscretizer().Discretize(ball, Resolution{14, 72});
  const Eigen::Vector3d c(1.5e-6, -0.8e-6, 0.6e-6);
  Eigen::VectorXd shift(grid.size()), lobed(grid.size());
  for (int k = 0; k < grid.size(); ++k) {
    // A sphere whose centre moved by c: radial deviation c.n to first order.
    shift(k) = 2e-6 + c.dot(grid.normal.col(k));
    const double beta = grid.column_angle(k % grid.columns);
    lobed(k) = 2e-6 * std::cos(3.0 * beta);
  }
  EXPECT_NEAR(EvaluateSphereForm(FormCharacteristic::kSphericity, g, grid, shift), 0.0, 1e-12);
  // Lobing that no centre or radius removes: sphericity is its full width 4 um.
  EXPECT_NEAR(EvaluateSphereForm(FormCharacteristic::kSphericity, g, grid, lobed), 4e-6, 1e-12);
  // Roundness of a row in its plane: 4 um * cos(latitude), largest at the row nearest the equator.
  const double y = grid.row_position(grid.rows / 2);
  const double cos_lat = std::sqrt(g.radius() * g.radius() - y * y) / g.radius();
  EXPECT_NEAR(EvaluateSphereForm(FormCharacteristic::kRoundness, g, grid, lobed), 4e-6 * cos_lat,
              1e-10);
  // A meridional barrel V = b y^2 is round in every row but not spherical: width b (B/2)^2 over
  // the sampled rows, minus what a centre shift along y and a radius change take out.
  Eigen::VectorXd barrel(grid.size());
  for (int k = 0; k < grid.size(); ++k) {
    const double yk = grid.centre(1, k);
    barrel(k) = 0.02 * yk * yk;  // 1/m: 0.98 um at the band's edge rows
  }
  EXPECT_LT(EvaluateSphereForm(FormCharacteristic::kRoundness, g, grid, barrel), 1e-10);
  const double sphericity = EvaluateSphereForm(FormCharacteristic::kSphericity, g, grid, barrel);
  const double edge = grid.row_position(grid.rows - 1);
  EXPECT_GT(sphericity, 0.0);
  EXPECT_LE(sphericity, 0.02 * edge * edge + 1e-12);
}

TEST(SphereForm, TwoPointSizesPairAntipodes) {
  const PartSpec ball = test::Ball();
  const SurfaceGrid grid = SphericalDiscretizer().Discretize(ball, Resolution{5, 8});
  Eigen::VectorXd v = Eigen::VectorXd::Zero(grid.size());
  v(grid.index(0, 1)) = 3e-6;  // antipode: row 4, column 5
  v(grid.index(4, 5)) = 2e-6;
  v(grid.index(2, 0)) = -4e-6;  // equator row pairs with itself, column 4
  const TwoPointRange r = TwoPointSizes(grid, v);
  EXPECT_DOUBLE_EQ(r.max, 5e-6);
  EXPECT_DOUBLE_EQ(r.min, -4e-6);
}

TEST(SphereGenerator, MeetsEveryToleranceAndUsesIt) {
  for (FormCharacteristic c : {FormCharacteristic::kRoundness, FormCharacteristic::kSphericity}) {
    PartSpec ball = test::Ball();
    ball.size.lower_deviation = -21e-6;
    ball.form.tolerance[c] = 4e-6;
    const SurfaceGrid grid = SphericalDiscretizer().Discretize(ball, Resolution{10, 36});
    double sum = 0.0;
    constexpr int kSeeds = 40;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      Rng rng(seed);
      const SkinModelShape sms =
          SphericalVariationGenerator().Generate(ball, grid, TextureMode::kExpected, rng);
      const double value = EvaluateSphereForm(c, GeometryOf(ball), grid, sms.form_part);
      EXPECT_LE(value, 4e-6 + 1e-12) << ToString(c) << " seed " << seed;
      sum += value;
      const TwoPointRange size = TwoPointSizes(grid, sms.variation);
      EXPECT_GE(size.min, -21e-6 - 1e-12);
      EXPECT_LE(size.max, 1e-12);
    }
    EXPECT_GT(sum / kSeeds, 0.2 * 4e-6) << ToString(c);
  }
}

}  // namespace
}  // namespace fitfeel::spherical
