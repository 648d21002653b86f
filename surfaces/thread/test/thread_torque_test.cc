// Tightening torque: the exact helicoid band integral against energy (frictionless screw),
// against the single-helix closed form and VDI 2230's tan(phi + rho') in the thin-band limit,
// the band values docs/threads.md quotes, the bearing annulus, and refusals.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/thread_torque.h"

namespace fitfeel::thread {
namespace {

constexpr double kSixtyDegrees = std::numbers::pi / 3.0;

// The contact band of an ISO metric thread: d/2 - 5H/8 to d/2 (thread_geometry.h).
double BandInnerRadius(double d, double pitch) {
  return 0.5 * d - 5.0 / 8.0 * pitch / (2.0 * std::tan(kSixtyDegrees / 2.0));
}

TEST(ThreadTorqueTest, GaussLegendreRuleIsExactForItsDegree) {
  for (int n = 1; n <= 30; ++n) {
    const QuadratureRule rule = GaussLegendreRule(n);
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], degree);
      const double exact = degree % 2 == 1 ? 0.0 : 2.0 / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-13) << n << " points, degree " << degree;
    }
  }
}

TEST(ThreadTorqueTest, FrictionlessScrewTurnsForceTimesAdvance) {
  // Torque times angle equals force times advance: T/F = P / (2 pi) for any band, flank angle
  // and pressure law (the flank's normal force does no work under the screw motion).
  for (double angle : {kSixtyDegrees, std::numbers::pi / 6.0, std::numbers::pi / 2.0}) {
    for (FlankPressure law : {FlankPressure::kWinkler, FlankPressure::kUniform}) {
      const TorqueRatio t = HelicoidTorqueRatio(1.5e-3, angle, 4.1e-3, 5e-3, 0.0, law);
      EXPECT_NEAR(t.total, 1.5e-3 / (2 * std::numbers::pi), 1e-15);
      EXPECT_NEAR(t.friction, 0.0, 1e-15);
      EXPECT_NEAR(t.efficiency(), 1.0, 1e-12);
    }
  }
  EXPECT_NEAR(VdiThreadTorqueRatio(9.026e-3, 1.5e-3, kSixtyDegrees, 0.0).total,
              1.5e-3 / (2 * std::numbers::pi), 1e-15);
  EXPECT_NEAR(SingleRadiusTorqueRatio(4.5e-3, 1.5e-3, kSixtyDegrees, 0.0).total,
              1.5e-3 / (2 * std::numbers::pi), 1e-15);
}

TEST(ThreadTorqueTest, ThinBandMeetsTheSingleHelixAndVdi) {
  // Band of +-1 nm about d2/2 of M10 x 1.5: the band integral is the single-helix formula, and
  // VDI's tan(phi + rho') differs from both only by taking alpha_n = alpha/2: +0.027 % at
  // mu = 0.16 (1.083078 against 1.082781 mm).
  const double d2 = PitchDiameter(10e-3, 1.5e-3);
  for (double mu : {0.08, 0.12, 0.16}) {
    const TorqueRatio band = HelicoidTorqueRatio(1.5e-3, kSixtyDegrees, 0.5 * d2 - 1e-9,
                                                 0.5 * d2 + 1e-9, mu, FlankPressure::kWinkler);
    const TorqueRatio helix = SingleRadiusTorqueRatio(0.5 * d2, 1.5e-3, kSixtyDegrees, mu);
    const TorqueRatio vdi = VdiThreadTorqueRatio(d2, 1.5e-3, kSixtyDegrees, mu);
    EXPECT_NEAR(band.total, helix.total, 1e-12 * helix.total) << mu;
    EXPECT_NEAR(vdi.total, band.total, 5e-4 * band.total) << mu;
    EXPECT_GT(vdi.total, band.total) << mu;
  }
  EXPECT_NEAR(SingleRadiusTorqueRatio(0.5 * d2, 1.5e-3, kSixtyDegrees, 0.16).total, 1.082781e-3,
              1e-9);
  EXPECT_NEAR(VdiThreadTorqueRatio(d2, 1.5e-3, kSixtyDegrees, 0.16).total, 1.083078e-3, 1e-9);
}

TEST(ThreadTorqueTest, FullBandAgainstVdiForM10) {
  // The contact band d/2 - 5H/8 .. d/2 has its friction radius above d2/2, so VDI's form lies
  // below the band integral: M10 x 1.5 by 1.27 % (mu 0.08) to 1.54 % (mu 0.16), M10 x 1.25 by
  // 1.09 % to 1.29 %. Band values from composite Simpson with 20000 intervals (mm):
  // M10 x 1.5, mu 0.12: Winkler 0.883105, uniform 0.883102, VDI 0.870433.
  const double d = 10e-3;
  struct Case {
    double pitch, mu, winkler_mm, vdi_below_percent;
  };
  for (const Case& c : {Case{1.5e-3, 0.08, 0.667279, 1.266}, Case{1.5e-3, 0.12, 0.883105, 1.435},
                        Case{1.5e-3, 0.16, 1.099978, 1.536}, Case{1.25e-3, 0.08, 0.632727, 1.090},
                        Case{1.25e-3, 0.16, 1.069956, 1.290}}) {
    const double r1 = BandInnerRadius(d, c.pitch);
    const TorqueRatio winkler =
        HelicoidTorqueRatio(c.pitch, kSixtyDegrees, r1, 0.5 * d, c.mu, FlankPressure::kWinkler);
    const TorqueRatio uniform =
        HelicoidTorqueRatio(c.pitch, kSixtyDegrees, r1, 0.5 * d, c.mu, FlankPressure::kUniform);
    const TorqueRatio vdi =
        VdiThreadTorqueRatio(PitchDiameter(d, c.pitch), c.pitch, kSixtyDegrees, c.mu);
    EXPECT_NEAR(winkler.total, c.winkler_mm * 1e-3, 1e-9) << c.pitch << " " << c.mu;
    // Winkler pressure ~ |n_y| hardly varies over the band: the two laws agree to 1e-5.
    EXPECT_NEAR(uniform.total, winkler.total, 1e-5 * winkler.total);
    EXPECT_NEAR(100 * (1 - vdi.total / winkler.total), c.vdi_below_percent, 0.001);
    EXPECT_DOUBLE_EQ(winkler.lead, c.pitch / (2 * std::numbers::pi));
    EXPECT_DOUBLE_EQ(winkler.lead + winkler.friction, winkler.total);
  }
  // The quadrature has converged long before 24 points.
  const double r1 = BandInnerRadius(d, 1.5e-3);
  EXPECT_NEAR(
      HelicoidTorqueRatio(1.5e-3, kSixtyDegrees, r1, 5e-3, 0.12, FlankPressure::kWinkler, 8).total,
      HelicoidTorqueRatio(1.5e-3, kSixtyDegrees, r1, 5e-3, 0.12, FlankPressure::kWinkler, 64).total,
      1e-16);
  // VDI's 0.16 P is P / (2 pi) rounded up by 0.53 %.
  EXPECT_NEAR(VdiThreadTorqueRatioApproximate(9.026e-3, 1.5e-3, 0.0).total /
                  (1.5e-3 / 2 / std::numbers::pi),
              1.00531, 1e-5);
}

TEST(ThreadTorqueTest, BearingAnnulus) {
  // M10: d_W = 14.63 mm, d_h = 11 mm. Uniform pressure: (2/3)(7.315^3 - 5.5^3) / (7.315^2 - 5.5^2)
  // = (2/3)(391.4210 - 166.375) / (53.5092 - 30.25) = 6.450343 mm; VDI's D_Km / 2 = 6.4075 mm,
  // 0.67 % less.
  EXPECT_NEAR(UniformAnnulusTorqueRatio(14.63e-3, 11e-3, 1.0), 6.450343e-3, 1e-9);
  EXPECT_NEAR(VdiBearingTorqueRatio(14.63e-3, 11e-3, 0.12), 0.12 * 6.4075e-3, 1e-12);
  for (double hole : {1e-3, 5e-3, 11e-3, 14e-3, 14.62e-3}) {
    EXPECT_GE(UniformAnnulusTorqueRatio(14.63e-3, hole, 0.1),
              VdiBearingTorqueRatio(14.63e-3, hole, 0.1));
  }
  // A thin annulus has one radius.
  EXPECT_NEAR(UniformAnnulusTorqueRatio(14.63e-3, 14.629e-3, 0.1),
              VdiBearingTorqueRatio(14.63e-3, 14.629e-3, 0.1), 1e-12);
}

TEST(ThreadTorqueTest, RefusesBadArgumentsNamingThem) {
  try {
    HelicoidTorqueRatio(1.5e-3, kSixtyDegrees, 5e-3, 4e-3, 0.1, FlankPressure::kWinkler);
    FAIL() << "inverted band";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("HelicoidTorqueRatio: inner_radius (5 mm) must be less than "
                        "outer_radius (4 mm)"),
              std::string::npos)
        << what;
  }
  EXPECT_THROW(HelicoidTorqueRatio(1.5e-3, kSixtyDegrees, 4e-3, 5e-3, 1.5, FlankPressure::kWinkler),
               UserError);
  EXPECT_THROW(HelicoidTorqueRatio(1.5e-3, 3.0, 4e-3, 5e-3, 0.1, FlankPressure::kWinkler),
               UserError);
  EXPECT_THROW(
      HelicoidTorqueRatio(-1.5e-3, kSixtyDegrees, 4e-3, 5e-3, 0.1, FlankPressure::kWinkler),
      UserError);
  EXPECT_THROW(
      HelicoidTorqueRatio(1.5e-3, kSixtyDegrees, 4e-3, 5e-3, 0.1, FlankPressure::kWinkler, 0),
      UserError);
  EXPECT_THROW(VdiThreadTorqueRatio(std::nan(""), 1.5e-3, kSixtyDegrees, 0.1), UserError);
  EXPECT_THROW(SingleRadiusTorqueRatio(0.0, 1.5e-3, kSixtyDegrees, 0.1), UserError);
  EXPECT_THROW(UniformAnnulusTorqueRatio(11e-3, 14.63e-3, 0.1), UserError);
  EXPECT_THROW(VdiBearingTorqueRatio(14.63e-3, 11e-3, -0.1), UserError);
  EXPECT_THROW(VdiTighteningTorque(10e-3, 1.5e-3, -1.0, 0.1, 14.63e-3, 11e-3, 0.1), UserError);
}

}  // namespace
}  // namespace fitfeel::thread
