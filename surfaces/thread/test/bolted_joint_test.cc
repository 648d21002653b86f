// VDI 2230 resiliences, plate cone, stress and permissible preload: hand values worked step by
// step, the properties the formulas must have, public table values, and refusals.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/fastener_tables.h"
#include "surfaces/thread/property_class.h"
#include "surfaces/thread/thread_torque.h"

namespace fitfeel::thread {
namespace {

// M10 x 1.5 bolt, ISO 4014 M10 x 40 (14 mm unthreaded shank inside the clamp), nut, two 10 mm
// steel plates, E = 205 GPa everywhere.
ThroughBolt M10ThroughTwoPlates() { return {10e-3, 1.5e-3, 20e-3, {{14e-3, 10e-3}}, 205e9, 205e9}; }

ClampedParts M10Plates(double outer_diameter) {
  return {14.6e-3, 11e-3, 20e-3, outer_diameter, 205e9};
}

TEST(BoltedJointTest, IsoThreadDiametersAndStressAreas) {
  EXPECT_NEAR(PitchDiameter(10e-3, 1.5e-3), 9.026e-3, 0.0005e-3);  // ISO 724
  EXPECT_NEAR(MinorDiameter(10e-3, 1.5e-3), 8.160e-3, 0.0005e-3);
  // ISO 898-1's stress areas A_s,nom (mm^2).
  const std::vector<std::pair<double, double>> areas = {{10, 58.0}, {12, 84.3}, {16, 157},
                                                        {20, 245},  {24, 353},  {36, 817}};
  for (const auto& [d, area] : areas) {
    const MetricFastener& f = MetricFastenerOf(d * 1e-3);
    EXPECT_NEAR(StressArea(f.nominal_diameter, f.pitch) * 1e6, area, 0.005 * area) << d;
  }
}

TEST(BoltedJointTest, BoltResilienceOfM10ByHand) {
  // mm and N: A_N = pi 10^2 / 4 = 78.53982; d3 = 10 - 1.226869 * 1.5 = 8.159697,
  // A_d3 = pi d3^2 / 4 = 52.29232; E_S = E_M = 205000 N/mm^2.
  //   head     0.5 * 10 / (205000 * 78.53982) = 3.105462e-7 mm/N
  //   shank    14       / (205000 * 78.53982) = 8.695294e-7
  //   free     (20 - 14) / (205000 * 52.29232) = 5.597054e-7
  //   engaged  0.5 * 10 / (205000 * 52.29232) = 4.664212e-7
  //   nut      0.4 * 10 / (205000 * 78.53982) = 2.484370e-7
  //   total                                   = 2.454639e-6 mm/N = 2.454639e-9 m/N
  const BoltResilience r = ThroughBoltResilience(M10ThroughTwoPlates());
  EXPECT_NEAR(r.head, 3.105462e-10, 1e-16);
  EXPECT_NEAR(r.shank, 8.695294e-10, 1e-16);
  EXPECT_NEAR(r.free_thread, 5.597054e-10, 1e-16);
  EXPECT_NEAR(r.engaged_thread, 4.664212e-10, 1e-16);
  EXPECT_NEAR(r.nut, 2.484370e-10, 1e-16);
  EXPECT_NEAR(r.total(), 2.454639e-9, 1e-15);
  EXPECT_DOUBLE_EQ(r.thread_pair() + r.series_with_thread_pair(), r.total());
  // A fully threaded bolt (ISO 4017) has the whole clamp length as free thread.
  ThroughBolt threaded = M10ThroughTwoPlates();
  threaded.shank.clear();
  EXPECT_NEAR(ThroughBoltResilience(threaded).free_thread, 20 / (205000 * 52.29232) * 1e-3, 1e-16);
}

TEST(BoltedJointTest, PlateResilienceOfM10ByHand) {
  // D_A = 40 mm: beta_L = 20 / 14.6 = 1.369863, ln(beta_L / 2) = -0.378436; y = 40 / 14.6,
  // ln y = 1.007858; tan phi = 0.362 - 0.012110 + 0.154202 = 0.504092;
  // D_A,Gr = 14.6 + 20 * 0.504092 = 24.6818 < 40: full cones.
  // delta_P = 2 ln[(25.6 * 13.6818) / (3.6 * 35.6818)] / (205000 pi 11 * 0.504092)
  //         = 2 ln(2.726676) / 3.571135e6 = 5.617742e-7 mm/N.
  const PlateResilience wide = ThroughBoltPlateResilience(M10Plates(40e-3));
  EXPECT_EQ(wide.body, DeformationBody::kCone);
  EXPECT_NEAR(wide.cone_tangent, 0.504092, 1e-6);
  EXPECT_NEAR(wide.limit_diameter, 24.6818e-3, 1e-7);
  EXPECT_NEAR(wide.resilience, 5.617742e-10, 1e-16);
  // D_A = 20 mm: ln y = ln(20 / 14.6) = 0.314711; tan phi = 0.362 - 0.012110 + 0.048151
  // = 0.398041; D_A,Gr = 22.5608 > 20: cones reaching D_A, then a sleeve.
  //   cones  2 / (11 * 0.398041) * ln((25.6 * 9) / (3.6 * 31)) = 0.456783 * 0.724896 = 0.331120
  //   sleeve 4 / (400 - 121) * (20 - 5.4 / 0.398041)        = 0.0143369 * 6.43356 = 0.092237
  //   delta_P = 0.423357 / (205000 pi) = 6.573600e-7 mm/N.
  const PlateResilience narrow = ThroughBoltPlateResilience(M10Plates(20e-3));
  EXPECT_EQ(narrow.body, DeformationBody::kConeAndSleeve);
  EXPECT_NEAR(narrow.cone_tangent, 0.398041, 1e-6);
  EXPECT_NEAR(narrow.resilience, 6.573600e-10, 1e-16);
  // Preload per turn past snug: 1.5 / (2.454639e-6 + 5.617742e-7) = 497279 N.
  const double per_turn =
      PreloadPerTurn(1.5e-3, ThroughBoltResilience(M10ThroughTwoPlates()).total(), wide.resilience);
  EXPECT_NEAR(per_turn, 497279, 1);
}

TEST(BoltedJointTest, PlateResilienceFallsUntilTheConesFitAndIsFlatBeyond) {
  // With the cone held at one angle, delta_P falls as D_A grows until D_A,Gr and is constant
  // beyond; the three bodies meet without a step.
  constexpr double kTangent = 0.45;
  const double limit = 14.6e-3 + 20e-3 * kTangent;
  double previous = INFINITY;
  for (double da = 12e-3; da < limit; da += 0.25e-3) {
    const double r = ThroughBoltPlateResilience(M10Plates(da), kTangent).resilience;
    EXPECT_LT(r, previous) << da;
    previous = r;
  }
  const double at_limit = ThroughBoltPlateResilience(M10Plates(limit), kTangent).resilience;
  for (double da : {limit * 1.01, 40e-3, 100e-3}) {
    EXPECT_DOUBLE_EQ(ThroughBoltPlateResilience(M10Plates(da), kTangent).resilience, at_limit);
  }
  const auto resilience = [&](double da) {
    return ThroughBoltPlateResilience(M10Plates(da), kTangent).resilience;
  };
  EXPECT_NEAR(resilience(limit * (1 - 1e-9)), at_limit, 1e-7 * at_limit);
  EXPECT_NEAR(resilience(14.6e-3 * (1 - 1e-9)), resilience(14.6e-3 * (1 + 1e-9)), 1e-7 * at_limit);
  EXPECT_EQ(ThroughBoltPlateResilience(M10Plates(14e-3), kTangent).body, DeformationBody::kSleeve);
  // Sleeve by hand: 20 / (205000 * pi/4 * (14^2 - 11^2)) = 1.656247e-6 mm/N.
  EXPECT_NEAR(resilience(14e-3), 1.656247e-9, 1e-15);
}

TEST(BoltedJointTest, VdiConeAngleKeepsTheResilienceMonotoneAndContinuous) {
  // VDI's tan phi grows with y = D_A / d_W, so delta_P keeps falling slowly beyond D_A,Gr.
  double previous = INFINITY;
  for (double da = 12e-3; da < 80e-3; da += 0.5e-3) {
    const double r = ThroughBoltPlateResilience(M10Plates(da)).resilience;
    EXPECT_LT(r, previous) << da;
    previous = r;
  }
  // D_A = D_A,Gr(D_A) found by bisection: the cone-and-sleeve and cone forms meet there.
  double low = 15e-3, high = 40e-3;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (ThroughBoltPlateResilience(M10Plates(mid)).body == DeformationBody::kCone ? high : low) = mid;
  }
  const PlateResilience below = ThroughBoltPlateResilience(M10Plates(low));
  const PlateResilience above = ThroughBoltPlateResilience(M10Plates(high));
  EXPECT_EQ(below.body, DeformationBody::kConeAndSleeve);
  EXPECT_EQ(above.body, DeformationBody::kCone);
  EXPECT_NEAR(below.resilience, above.resilience, 1e-9 * above.resilience);
}

TEST(BoltedJointTest, PermissiblePreloadAndTorqueMatchVdiTables) {
  // VDI 2230 (2003) table of assembly preloads F_M,Tab (nu = 0.9) and tightening torques M_A
  // (mu_K = mu_G) for fine-thread hexagon bolts, as published in fastener suppliers' catalogues:
  // d_W the ISO 4014 grade A minimum, d_h ISO 273 medium. The table rounds down, and its
  // diameters are rounded, so the formula lies up to 0.3 % above it.
  struct Row {
    double d, pitch, dw, dh;
    const char* property_class;
    double mu, preload_kn, torque_nm;
  };
  const std::vector<Row> rows = {
      {8, 1, 11.63, 9, "8.8", 0.10, 20.7, 22.8},
      {8, 1, 11.63, 9, "8.8", 0.12, 20.2, 26.1},
      {8, 1, 11.63, 9, "8.8", 0.14, 19.7, 29.2},
      {8, 1, 11.63, 9, "10.9", 0.12, 29.7, 38.3},
      {8, 1, 11.63, 9, "12.9", 0.14, 33.9, 50.1},
      {10, 1.25, 14.63, 11, "8.8", 0.10, 32.4, 44},
      {10, 1.25, 14.63, 11, "8.8", 0.12, 31.6, 51},
      {10, 1.25, 14.63, 11, "8.8", 0.14, 30.8, 57},
      {10, 1.25, 14.63, 11, "10.9", 0.12, 46.4, 75},
      {10, 1.25, 14.63, 11, "12.9", 0.10, 55.6, 76},
      {12, 1.25, 16.63, 13.5, "8.8", 0.12, 48.0, 90},
      {12, 1.25, 16.63, 13.5, "10.9", 0.14, 68.7, 149},
      {12, 1.25, 16.63, 13.5, "12.9", 0.12, 82.5, 155},
  };
  for (const Row& row : rows) {
    const double d = row.d * 1e-3, pitch = row.pitch * 1e-3;
    const double yield = BoltPropertyClass::Parse(row.property_class).min_yield_strength(d);
    const double preload = PermissibleAssemblyPreload(d, pitch, yield, row.mu);
    const std::string label = "M" + std::to_string(row.d) + " " + row.property_class;
    EXPECT_GE(preload, row.preload_kn * 1e3 * 0.9995) << label << " mu " << row.mu;
    EXPECT_LE(preload, row.preload_kn * 1e3 * 1.003) << label << " mu " << row.mu;
    const double torque =
        VdiTighteningTorque(d, pitch, preload, row.mu, row.dw * 1e-3, row.dh * 1e-3, row.mu);
    // Torques are tabulated to 0.1 N m below 40 N m and to 1 N m above.
    const double rounding = row.torque_nm < 40 ? 0.05 : 0.5;
    EXPECT_NEAR(torque, row.torque_nm, rounding + 0.005 * row.torque_nm)
        << label << " mu " << row.mu;
  }
  // Coarse M10 x 1.5, 8.8, mu_G = mu_K = 0.12 by the same formulas: d2 = 9.025722, d3 = 8.159697,
  // d0 = 8.592709, A_0 = 57.9896 mm^2; bracket 1.5 (9.025722 / 8.592709)(1.5 / (pi 9.025722)
  // + 0.1386) = 0.301722; F = 57.9896 * 0.9 * 640 / sqrt(1 + 3 * 0.301722^2) = 29603 N;
  // M_A = 29603 (0.24 + 0.58 * 9.025722 * 0.12 + 0.12 * 12.815 / 2) = 48.46 N m.
  const double coarse = PermissibleAssemblyPreload(10e-3, 1.5e-3, 640e6, 0.12);
  EXPECT_NEAR(coarse, 29603, 1);
  EXPECT_NEAR(VdiTighteningTorque(10e-3, 1.5e-3, coarse, 0.12, 14.63e-3, 11e-3, 0.12), 48.46, 0.01);
}

TEST(BoltedJointTest, ElasticUtilisationDuringTightening) {
  // At F_M,zul with VDI's thread torque M_G = F (d2/2)(P / (pi d2) + 1.155 mu), the elastic
  // W_P = pi d0^3 / 16 gives tau / sigma = 2 (d2 / d0)(...), where F_M,zul's 3/2 assumed the
  // plastic pi d0^3 / 12: the utilisation is 0.9 sqrt(1 + 3 (2 b / 1.5)^2) / sqrt(1 + 3 b^2)
  // with b = 0.301722, = 0.9 * 1.218822 / 1.128321 = 0.972189.
  const double d = 10e-3, pitch = 1.5e-3, mu = 0.12;
  const double preload = PermissibleAssemblyPreload(d, pitch, 640e6, mu);
  const double d2 = PitchDiameter(d, pitch);
  const double torque = preload * 0.5 * d2 * (pitch / (std::numbers::pi * d2) + 1.155 * mu);
  const AssemblyStress s = TighteningStress(d, pitch, preload, torque, 640e6);
  EXPECT_NEAR(s.utilisation, 0.972189, 1e-6);
  EXPECT_NEAR(s.tensile, preload / StressArea(d, pitch), 1e-6);
  EXPECT_NEAR(s.equivalent, std::hypot(s.tensile, std::sqrt(3.0) * s.torsional), 1e-3);
  // Without torque the utilisation is the tensile stress over the yield strength.
  EXPECT_NEAR(TighteningStress(d, pitch, preload, 0.0, 640e6).utilisation,
              preload / StressArea(d, pitch) / 640e6, 1e-12);
}

TEST(BoltedJointTest, RefusesBadArgumentsNamingThem) {
  const auto message = [](const auto& call) {
    try {
      call();
    } catch (const UserError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  ClampedParts parts = M10Plates(40e-3);
  parts.hole_diameter = 15e-3;
  const std::string hole = message([&] { ThroughBoltPlateResilience(parts); });
  EXPECT_NE(hole.find("hole_diameter (15 mm) must be less than bearing_diameter (14.6 mm)"),
            std::string::npos)
      << hole;
  parts = M10Plates(std::nan(""));
  EXPECT_NE(message([&] { ThroughBoltPlateResilience(parts); }).find("outer_diameter"),
            std::string::npos);
  parts = M10Plates(10e-3);  // D_A below the hole
  EXPECT_THROW(ThroughBoltPlateResilience(parts), UserError);
  parts = M10Plates(40e-3);
  parts.modulus = -1;
  EXPECT_THROW(ThroughBoltPlateResilience(parts), UserError);
  EXPECT_THROW(ThroughBoltPlateResilience(M10Plates(40e-3), 0.0), UserError);

  ThroughBolt bolt = M10ThroughTwoPlates();
  bolt.shank = {{25e-3, 10e-3}};
  const std::string shank = message([&] { ThroughBoltResilience(bolt); });
  EXPECT_NE(shank.find("total shank length"), std::string::npos) << shank;
  bolt.shank = {{5e-3, 11e-3}};
  EXPECT_THROW(ThroughBoltResilience(bolt), UserError);
  bolt = M10ThroughTwoPlates();
  bolt.pitch = 4e-3;
  const std::string pitch = message([&] { ThroughBoltResilience(bolt); });
  EXPECT_NE(pitch.find("ThroughBoltResilience: pitch must be in [0 m"), std::string::npos) << pitch;
  bolt = M10ThroughTwoPlates();
  bolt.clamp_length = 0.0;
  EXPECT_THROW(ThroughBoltResilience(bolt), UserError);
  bolt = M10ThroughTwoPlates();
  bolt.nut_modulus = INFINITY;
  EXPECT_THROW(ThroughBoltResilience(bolt), UserError);

  EXPECT_THROW(PermissibleAssemblyPreload(10e-3, 1.5e-3, 640e6, 0.12, 0.0), UserError);
  EXPECT_THROW(PermissibleAssemblyPreload(10e-3, 1.5e-3, 640e6, 0.12, 1.1), UserError);
  EXPECT_THROW(PermissibleAssemblyPreload(10e-3, 1.5e-3, 640e6, -0.1), UserError);
  EXPECT_THROW(TighteningStress(10e-3, 1.5e-3, -1.0, 0.0, 640e6), UserError);
  EXPECT_THROW(TighteningStress(10e-3, 1.5e-3, 1.0, 0.0, 0.0), UserError);
  EXPECT_THROW(PreloadPerTurn(1.5e-3, 0.0, 1e-9), UserError);
  EXPECT_THROW(ThroughBoltConeTangent(0.01e-3, 500e-3, 500e-3), UserError);
}

}  // namespace
}  // namespace fitfeel::thread
