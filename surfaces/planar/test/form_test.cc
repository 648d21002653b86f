// Minimum-zone form evaluation against the closed forms of docs/oracles.md and brute force.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "surfaces/planar/planar_form.h"

namespace fitfeel::planar {
namespace {

TEST(PlanarFormTest, ParabolicProfileWithTiltHasStraightnessAL2Over4) {
  // docs/oracles.md: profile a x^2 over length L, any added tilt -> straightness a L^2 / 4.
  const double a = 3.0, length = 0.04;
  for (double tilt : {0.0, 1e-4, -5e-3}) {
    std::vector<double> t, v;
    for (int k = 0; k <= 200; ++k) {
      const double x = -0.5 * length + length * k / 200.0;
      t.push_back(x);
      v.push_back(a * x * x + tilt * x);
    }
    EXPECT_NEAR(MinZoneStraightness(t, v).width, a * length * length / 4.0, 1e-15) << tilt;
    EXPECT_NEAR(MinZoneStraightness(t, v).slope, tilt, 1e-12);
  }
}

TEST(PlanarFormTest, SaddleHasFlatness2AH2) {
  // docs/oracles.md: saddle a (x^2 - y^2) on [-h, h]^2 -> flatness 2 a h^2.
  const double a = 2.0, h = 0.01;
  std::vector<double> y, z, v;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) {
      const double yy = -h + 2 * h * i / 20.0, zz = -h + 2 * h * j / 20.0;
      y.push_back(yy);
      z.push_back(zz);
      v.push_back(a * (yy * yy - zz * zz) + 3e-3 * yy - 1e-3 * zz + 5e-6);
    }
  }
  const PlaneZone zone = MinZoneFlatness(y, z, v);
  EXPECT_NEAR(zone.width, 2 * a * h * h, 1e-15);
  EXPECT_NEAR(zone.slope_y, 3e-3, 1e-9);
  EXPECT_NEAR(zone.slope_z, -1e-3, 1e-9);
}

TEST(PlanarFormTest, StraightnessEqualsBruteForceOverAllPairSlopes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1e-5, 1e-5);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> t, v;
    const int n = 3 + trial % 17;
    for (int k = 0; k < n; ++k) {
      t.push_back(1e-3 * k + (trial % 2) * 1e-4 * u(rng) * 1e5);
      v.push_back(u(rng));
    }
    // The minimiser's slope is the slope through two of the points.
    double brute = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (t[i] == t[j]) continue;
        const double s = (v[j] - v[i]) / (t[j] - t[i]);
        double lo = 1e300, hi = -1e300;
        for (int k = 0; k < n; ++k) {
          lo = std::min(lo, v[k] - s * t[k]);
          hi = std::max(hi, v[k] - s * t[k]);
        }
        brute = std::min(brute, hi - lo);
      }
    }
    EXPECT_NEAR(MinZoneStraightness(t, v).width, brute, 1e-18) << trial;
  }
}

TEST(PlanarFormTest, FlatnessIsNeverAboveAnyPlaneAndMatchesARandomSearch) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1e-5, 1e-5);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<double> y, z, v;
    for (int i = 0; i < 8; ++i) {
      for (int j = 0; j < 3; ++j) {
        y.push_back(2.5e-3 * i);
        z.push_back(1e-3 * j);
        v.push_back(u(rng));
      }
    }
    const PlaneZone zone = MinZoneFlatness(y, z, v);
    EXPECT_NEAR(RangeAlong(y, z, v, zone.slope_y, zone.slope_z), zone.width, 1e-18);
    // No plane through three of the points does better (the optimum is set by such planes).
    for (int probe = 0; probe < 2000; ++probe) {
      const double a = u(rng) * 200.0, c = u(rng) * 500.0;
      EXPECT_GE(RangeAlong(y, z, v, zone.slope_y + a, zone.slope_z + c), zone.width - 1e-18);
    }
  }
}

TEST(PlanarFormTest, DegenerateInputs) {
  EXPECT_EQ(MinZoneStraightness({}, {}).width, 0.0);
  EXPECT_EQ(MinZoneStraightness({1.0}, {2.0}).width, 0.0);
  EXPECT_DOUBLE_EQ(MinZoneStraightness({1.0, 1.0}, {2.0, 5.0}).width, 3.0);
  EXPECT_EQ(MinZoneFlatness({0.0, 1.0, 2.0}, {0.0, 0.0, 0.0}, {1.0, 2.0, 3.0}).width, 0.0);
}

}  // namespace
}  // namespace fitfeel::planar
