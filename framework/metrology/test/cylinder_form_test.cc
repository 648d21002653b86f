#include "framework/metrology/cylinder_form.h"

#include <cmath>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

#include "framework/testing/units.h"

namespace fitfeel::metrology {
namespace {

using test_support::kPi;

// Grid with rows at both ends of [0, L] so the extremes of the analytic shapes are sampled.
CylinderSamples Grid(int m, int n, double L, const std::function<double(double, double)>& v) {
  CylinderSamples s;
  s.nominal_radius = 0.01;
  s.y.resize(m);
  s.theta.resize(n);
  s.deviation.resize(m, n);
  for (int i = 0; i < m; ++i) s.y(i) = L * i / (m - 1);
  for (int j = 0; j < n; ++j) s.theta(j) = 2.0 * kPi * j / n;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) s.deviation(i, j) = v(s.y(i), s.theta(j));
  return s;
}

TEST(Cylindricity, ConeGivesSlopeTimesLength) {
  const double L = 0.04, c = 2e-4;  // 8 um over 40 mm
  const auto s = Grid(21, 48, L, [&](double z, double) { return c * z; });
  EXPECT_NEAR(MinimumZoneCylindricity(s).value, c * L, 1e-12);
}

TEST(Cylindricity, BarrelGivesQuarterCurvatureLengthSquared) {
  const double L = 0.03, b = 0.02;  // b L^2 / 4 = 4.5 um
  const auto s = Grid(31, 36, L, [&](double z, double) { return b * (z - L / 2) * (z - L / 2); });
  EXPECT_NEAR(MinimumZoneCylindricity(s).value, b * L * L / 4, 1e-12);
}

TEST(Cylindricity, IgnoresASmallAxisOffsetAndTilt) {
  // A perfect cylinder whose axis is shifted by 3 um and tilted by 1e-4: zero cylindricity up to
  // the linearisation (e^2/2R, here below 1e-9 m) and the found axis is the shifted one.
  const double L = 0.02;
  const auto s = Grid(11, 36, L, [&](double z, double t) {
    return (3e-6 + 1e-4 * z) * std::cos(t) - 2e-6 * std::sin(t);
  });
  const auto r = MinimumZoneCylindricity(s);
  EXPECT_NEAR(r.value, 0.0, 1e-12);
  EXPECT_NEAR(r.x0, 3e-6, 1e-12);
  EXPECT_NEAR(r.tx, 1e-4, 1e-10);
  EXPECT_NEAR(r.z0, -2e-6, 1e-12);
}

TEST(AxisStraightness, PlanarBowGivesItsSag) {
  const double L = 0.06, sag = 8e-6;
  // Sections displaced along x by a parabolic bow of sag `sag` (zero at the ends).
  const auto s = Grid(25, 48, L, [&](double z, double t) {
    const double u = 2.0 * z / L - 1.0;
    return sag * (1.0 - u * u) * std::cos(t);
  });
  const Eigen::Matrix2Xd centres = SectionCentres(s);
  for (int i = 0; i < 25; ++i) {
    const double u = 2.0 * s.y(i) / L - 1.0;
    EXPECT_NEAR(centres(0, i), sag * (1.0 - u * u), 1e-12);
  }
  EXPECT_NEAR(AxisStraightness(s.y, centres), sag, 1e-11);
}

TEST(AxisStraightness, HelixFitsItsOwnCylinder) {
  // Centres on a helix of radius rho (three turns): the smallest containing cylinder is the
  // helix's, diameter 2 rho; the 128-gon bound is within 0.03 %.
  const int m = 90;
  const double rho = 4e-6;
  Eigen::VectorXd y(m);
  Eigen::Matrix2Xd c(2, m);
  for (int i = 0; i < m; ++i) {
    y(i) = 0.05 * i / (m - 1);
    const double a = 6.0 * kPi * i / m;
    c.col(i) << rho * std::cos(a) + 1e-3, rho * std::sin(a);
  }
  const double value = AxisStraightness(y, c);
  EXPECT_LE(value, 2 * rho * 1.0003);
  EXPECT_GE(value, 2 * rho * (1.0 - 1e-9));
}

TEST(AxisStraightness, StraightButTiltedAxisIsStraight) {
  Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(10, 0.0, 0.02);
  Eigen::Matrix2Xd c(2, 10);
  for (int i = 0; i < 10; ++i) c.col(i) << 1e-3 * y(i) + 2e-6, -5e-4 * y(i);
  EXPECT_NEAR(AxisStraightness(y, c), 0.0, 1e-15);
}

TEST(ProfileStraightness, ParabolaWithTiltGivesQuarterALSquared) {
  const double a = 0.01, L = 0.02, tilt = 1e-3;
  Eigen::Matrix2Xd p(2, 41);
  for (int i = 0; i < 41; ++i) {
    const double x = L * i / 40;
    p.col(i) << x, a * x * x + tilt * x - 3e-6;
  }
  // Minimum width is measured perpendicular to the chord, of slope a L + tilt.
  const double slope = a * L + tilt;
  const double expected = a * L * L / 4 / std::sqrt(1.0 + slope * slope);
  EXPECT_NEAR(ProfileStraightness(p), expected, 1e-18);
  EXPECT_NEAR(ProfileStraightness(p), a * L * L / 4, 1e-12);
}

TEST(ProfileStraightness, StraightLineIsZero) {
  Eigen::Matrix2Xd p(2, 5);
  p << 0, 1, 2, 3, 4, 1, 3, 5, 7, 9;
  EXPECT_EQ(ProfileStraightness(p), 0.0);
}

TEST(TwoPointSizes, EvenHarmonicsChangeSizesOddOnesDoNot) {
  const double a = 3e-6;
  const auto oval = Grid(3, 48, 0.01, [&](double, double t) { return 1e-6 + a * std::cos(2 * t); });
  const SizeRange r = TwoPointSizes(oval);
  EXPECT_NEAR(r.min, 2e-6 - 2 * a, 1e-18);
  EXPECT_NEAR(r.max, 2e-6 + 2 * a, 1e-18);
  const auto trilobe = Grid(3, 48, 0.01, [&](double, double t) { return a * std::cos(3 * t); });
  EXPECT_NEAR(TwoPointSizes(trilobe).min, 0.0, 1e-18);
  EXPECT_NEAR(TwoPointSizes(trilobe).max, 0.0, 1e-18);
  const auto odd = Grid(3, 7, 0.01, [](double, double) { return 0.0; });
  EXPECT_THROW(TwoPointSizes(odd), std::invalid_argument);
}

}  // namespace
}  // namespace fitfeel::metrology
