// The planar law against hand calculations of its elastic model (README.md).
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "framework/testing/fem_data.h"
#include "surfaces/planar/planar_contact_analyzer.h"
#include "surfaces/planar/planar_generator.h"
#include "surfaces/planar/planar_discretizer.h"
#include "surfaces/planar/planar_law.h"
#include "surfaces/planar/test/test_support.h"

namespace fitfeel::planar {
namespace {

using testing::MakePart;

TEST(PlanarElasticModelTest, RectangleSelfPotentialMatchesBoussinesqFootingFactors) {
  // A flexible square footing settles on average 0.946 p B (1 - nu^2) / E (Timoshenko & Goodier):
  // J(1, 1) / pi = 0.9464.
  EXPECT_NEAR(RectangleSelfPotential(1.0, 1.0) / std::numbers::pi, 0.94640, 1e-5);
  EXPECT_NEAR(RectangleSelfPotential(1.0, 1.0), 2.973210, 1e-6);
  // Symmetric and homogeneous of degree 3.
  EXPECT_NEAR(RectangleSelfPotential(3e-3, 40e-3), RectangleSelfPotential(40e-3, 3e-3), 1e-20);
  EXPECT_NEAR(RectangleSelfPotential(3e-3, 40e-3), 1e-9 * RectangleSelfPotential(3.0, 40.0), 1e-18);
  // Hand value for the key flank strip h = 3 mm, L = 40 mm.
  EXPECT_NEAR(RectangleSelfPotential(3e-3, 40e-3), 2.741890e-6, 1e-12);
}

TEST(PlanarElasticModelTest, KeyOfEightMillimetresHandCalculation) {
  // Steel key 8 x 7, flank in contact h = 3 mm, L = 40 mm; E = 210 GPa, nu = 0.3, delta = 1 um.
  // c_key  = 8e-3 * 0.91 / 210e9                       = 3.46667e-14 m/Pa
  // c_wall = 0.91 * 2.74189e-6 / (pi 210e9 * 1.2e-4)   = 3.15167e-14 m/Pa
  // p = 2 delta / (c_key + 2 c_wall)                    = 20.4708 MPa
  EXPECT_NEAR(BlockCompliance(8e-3, 210e9, 0.3), 3.466667e-14, 1e-19);
  EXPECT_NEAR(HalfSpaceStripCompliance(3e-3, 40e-3, 210e9, 0.3), 3.151672e-14, 1e-19);
  const double p = 1e-6 * PressurePerInterference(8e-3, 3e-3, 40e-3, 210e9, 0.3, 210e9, 0.3);
  EXPECT_NEAR(p, 20.4708e6, 0.0001e6);
}

// tools/fem/data/key.csv: CalculiX in 3-D (tools/fem/key.py), the 8 mm key pressed over a 2.6 mm
// flank (the key-parallel scene's) between two steel walls far larger than the strip, 5 um of
// interference per face, engaged over 40 and 10 mm: the flank's normal force against the law's
// P(L) delta h L, within 10 % (measured +0.7 % and +2.9 %). A rigid key (1000 times
// stiffer) presses the wall alone: delta h L / c_wall, the law's lateral stiffness per pressed
// flank times delta (measured -8.5 %: a rigid flank concentrates the pressure at the strip's
// edges, stiffer than the uniform pressure's mean displacement J says, and the 200 mm wall is
// about 2 % stiffer than a half-space).
TEST(PlanarElasticModelTest, FlankForceAgreesWithCalculix) {
  for (const char* name : {"key-8x2.6-L40", "key-8x2.6-L10", "key-rigid-8x2.6-L40"}) {
    const double width = test_support::FemValue("key.csv", name, 1) * 1e-3;
    const double height = test_support::FemValue("key.csv", name, 2) * 1e-3;
    const double length = test_support::FemValue("key.csv", name, 3) * 1e-3;
    const double delta = test_support::FemValue("key.csv", name, 4) * 1e-6;
    const double key_modulus = 210e9 * test_support::FemValue("key.csv", name, 5);
    const double fem = test_support::FemValue("key.csv", name, 6);
    const double law =
        PressurePerInterference(width, height, length, key_modulus, 0.3, 210e9, 0.3) * delta *
        height * length;
    std::printf("%s: FEM %.1f N, law %.1f N (%+.1f %%)\n", name, fem, law,
                100.0 * (law / fem - 1.0));
    EXPECT_LT(std::abs(law / fem - 1.0), 0.10) << name;
  }
}

TEST(PlanarLawTest, UniformInterferencePressInForceMatchesTheHandCalculation) {
  // Through the analyzer: key 1 um per flank wider than its keyway, fully engaged, mu = 0.15,
  // 10 mm/s. F = mu * 2 * p * h * L = 0.15 * 2 * 20.4708 MPa * 3 mm * 40 mm = 736.95 N.
  PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 3e-3);
  PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 60e-3, 3e-3);
  SkinModelShape k, s;
  k.grid = PlanarDiscretizer().Discretize(key, Resolution{});
  s.grid = PlanarDiscretizer().Discretize(slot, Resolution{});
  k.variation = Eigen::VectorXd::Constant(k.grid.size(), 1e-6);
  s.variation = Eigen::VectorXd::Zero(s.grid.size());
  ModelSettings settings;
  settings.friction = 0.15;
  PlanarContactAnalyzer analyzer;
  analyzer.Prepare(key, k, slot, s, settings);
  PlanarGpsLaw law;
  law.Prepare(key, slot, settings);
  ContactState state;
  MatingPose pose;
  pose.depth = 50e-3;
  analyzer.Evaluate(pose, &state);
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  Wrench w;
  law.Evaluate(state, motion, &w);
  EXPECT_NEAR(w.force.y(), -736.95, 0.01);
  // The balance position is found to 1e-18 m; the auto stiffness is 2.5e9 N/m.
  EXPECT_NEAR(w.force.x(), 0.0, 1e-6);
  // Pulled out, friction reverses.
  motion.velocity.y() = -0.01;
  law.Evaluate(state, motion, &w);
  EXPECT_NEAR(w.force.y(), 736.95, 0.01);
}

TEST(PlanarLawTest, ClearanceSpringWithCoulombFrictionIsEquationNineInOneAxis) {
  PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 3e-3);
  PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 60e-3, 3e-3);
  ModelSettings settings;
  settings.friction = 0.2;
  settings.contact_stiffness = 2e6;  // 2 N/um
  PlanarGpsLaw law;
  law.Prepare(key, slot, settings);
  ContactState state;
  state.engaged = true;
  state.engaged_length = 40e-3;
  state.engaged_area = 2 * 3e-3 * 40e-3;
  state.penetration = 3e-6;
  state.offset_angle = std::numbers::pi;  // pushed towards -x
  state.penetration_direction = {-1.0, 0.0};
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  Wrench w;
  law.Evaluate(state, motion, &w);
  EXPECT_NEAR(w.force.x(), 6.0, 1e-9);  // pushed back towards +x by k e
  EXPECT_NEAR(w.force.z(), 0.0, 1e-9);
  EXPECT_NEAR(w.force.y(), -0.2 * 6.0 * std::tanh(10.0), 1e-9);
  // Auto stiffness in clearance: the key rests on one wall and translates into it, h L / c_wall
  // (c_wall = 3.15167e-14 m/Pa above): 3.8075e9 N/m.
  settings.contact_stiffness = 0.0;
  law.Prepare(key, slot, settings);
  law.Evaluate(state, motion, &w);
  const double k = 3e-3 * 40e-3 / HalfSpaceStripCompliance(3e-3, 40e-3, 210e9, 0.3);
  EXPECT_NEAR(k, 3.8075e9, 0.0001e9);
  EXPECT_NEAR(w.force.x(), k * 3e-6, 1e-6 * k * 3e-6);
}

TEST(PlanarLawTest, ReportsThePressurePerInterferenceAtFullEngagementForPressureMaps) {
  // Key 40 mm long in a 60 mm keyway: full engagement is the key's 40 mm, h = 3 mm: the hand
  // calculation above, 20.4708 MPa per um.
  PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 3e-3);
  PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 60e-3, 3e-3);
  ModelSettings settings;
  settings.friction = 0.15;
  PlanarGpsLaw law;
  law.Prepare(key, slot, settings);
  EXPECT_NEAR(law.PressurePerInterference() * 1e-12, 20.4708, 0.0001);
  EXPECT_EQ(law.PressurePerInterference(), law.PressurePerInterferenceAt(40e-3));
  // A keyway shorter than the key: its length is the full engagement.
  PartSpec short_slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 25e-3, 3e-3);
  law.Prepare(key, short_slot, settings);
  const double expected = PressurePerInterference(8e-3, 3e-3, 25e-3, 210e9, 0.3, 210e9, 0.3);
  EXPECT_NEAR(law.PressurePerInterference(), expected, 1e-12 * expected);
}

TEST(PlanarLawTest, LateralSupportGrowsMonotonicallyWithOffsetForAnyForm) {
  // The constrained stage settles a part under its radial load by bracketing the root of the
  // support along the load: -F . u must be non-decreasing in the offset s along u. In clearance
  // the spring pushes back from the assembly space (x minus its projection on a convex set: a
  // monotone map), under interference about the balance position. Over seeds, for a key (one
  // pair of flanks) and a square shaft (two pairs), at partial and full engagement.
  for (int faces : {2, 4}) {
    PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 2.6e-3, faces);
    PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 45e-3, 2.6e-3, faces);
    key.form.tolerance[FormCharacteristic::kFlatness] = 12e-6;
    slot.form.tolerance[FormCharacteristic::kFlatness] = 12e-6;
    const SurfaceGrid gk = PlanarDiscretizer().Discretize(key, Resolution{});
    const SurfaceGrid gs = PlanarDiscretizer().Discretize(slot, Resolution{});
    int rising = 0;
    for (int seed = 1; seed <= 12; ++seed) {
      Rng rng(seed);
      const SkinModelShape k =
          PlanarVariationGenerator().Generate(key, gk, TextureMode::kExpected, rng);
      const SkinModelShape s =
          PlanarVariationGenerator().Generate(slot, gs, TextureMode::kExpected, rng);
      ModelSettings settings;
      settings.friction = 0.15;
      PlanarContactAnalyzer analyzer;
      analyzer.Prepare(key, k, slot, s, settings);
      PlanarGpsLaw law;
      law.Prepare(key, slot, settings);
      MatingMotion motion;
      motion.velocity.y() = 0.01;
      for (double depth : {20e-3, 40e-3}) {
        for (int d = 0; d < 8; ++d) {
          const Eigen::Vector2d u(std::cos(d * std::numbers::pi / 4 + 0.1),
                                  std::sin(d * std::numbers::pi / 4 + 0.1));
          double previous = -std::numeric_limits<double>::infinity();
          for (double t = -60e-6; t <= 60e-6; t += 0.5e-6) {
            MatingPose pose;
            pose.depth = depth;
            pose.offset = t * u;
            ContactState state;
            analyzer.Evaluate(pose, &state);
            Wrench w;
            law.Evaluate(state, motion, &w);
            const double support = -(w.force.x() * u.x() + w.force.z() * u.y());
            ASSERT_GE(support, previous - 1e-9 * std::abs(previous))
                << faces << " " << seed << " " << depth << " " << t;
            if (support > previous + 1.0) ++rising;
            previous = support;
          }
        }
      }
    }
    EXPECT_GT(rising, 500) << faces;  // the walls are reached
  }
}

TEST(PlanarLawTest, NoForceWhenNotEngagedOrAtRest) {
  PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 3e-3);
  PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 60e-3, 3e-3);
  ModelSettings settings;
  settings.friction = 0.15;
  PlanarGpsLaw law;
  law.Prepare(key, slot, settings);
  ContactState state;
  state.interference_volume = 1e-12;
  Wrench w;
  law.Evaluate(state, MatingMotion{}, &w);
  EXPECT_EQ(w.force.norm(), 0.0);
  state.engaged = true;
  state.engaged_length = 10e-3;
  law.Evaluate(state, MatingMotion{}, &w);
  EXPECT_EQ(w.force.y(), 0.0);  // at rest the regularised friction is zero
}

}  // namespace
}  // namespace fitfeel::planar

namespace fitfeel::planar {
namespace {

// A key pressed between both walls and pushed sideways by e translates as a whole;
// one wall is compressed by e more, the other by e less, so the pair resists with
// 2 A / c_wall (A = h L one flank's area), not one flank's series value P A:
//   c_wall = 3.15167e-14 m/Pa (h = 3 mm, L = 40 mm, hand value above), A = 1.2e-4 m^2
//   k = 2 * 1.2e-4 / 3.15167e-14 = 7.6151e9 N/m, against P A = 20.4708e12 * 1.2e-4 = 2.4565e9.
// The normal force on the flanks does not change (one gains what the other loses), so the
// friction stays mu * 2 p h L.
TEST(PlanarLawTest, LateralStiffnessComesFromBothWalls) {
  PartSpec key = testing::MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 3e-3);
  PartSpec slot = testing::MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 60e-3, 3e-3);
  SkinModelShape k, s;
  k.grid = PlanarDiscretizer().Discretize(key, Resolution{});
  s.grid = PlanarDiscretizer().Discretize(slot, Resolution{});
  k.variation = Eigen::VectorXd::Constant(k.grid.size(), 1e-6);
  s.variation = Eigen::VectorXd::Zero(s.grid.size());
  ModelSettings settings;
  settings.friction = 0.15;
  settings.contact_stiffness = 0.0;  // auto: the law's own elastic model
  PlanarContactAnalyzer analyzer;
  analyzer.Prepare(key, k, slot, s, settings);
  PlanarGpsLaw law;
  law.Prepare(key, slot, settings);
  EXPECT_NEAR(law.LateralStiffness(40e-3, 1.2e-4, 2), 7.6151e9, 0.0001e9);
  EXPECT_NEAR(law.LateralStiffness(40e-3, 1.2e-4, 2) / (law.PressurePerInterferenceAt(40e-3) * 1.2e-4),
              3.10, 0.01);
  MatingPose pose;
  pose.depth = 50e-3;
  pose.offset = Eigen::Vector2d(0.2e-6, 0.0);  // within the 1 um interference: both walls pressed
  ContactState contact;
  analyzer.Evaluate(pose, &contact);
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  Wrench w;
  law.Evaluate(contact, motion, &w);
  EXPECT_NEAR(w.force.x(), -7.6151e9 * 0.2e-6, 0.0001e9 * 0.2e-6);
  EXPECT_NEAR(w.force.y(), -736.95, 0.01);  // no double count of the lateral force
}

}  // namespace
}  // namespace fitfeel::planar

namespace fitfeel::planar {
namespace {

// A square shaft twisted in its square hole (both ideal, 3 um of clearance on every side): its
// flats' edges, half the flat's height h/2 = 9 mm from their centre lines, swing across the
// clearance at theta = 3 um / 9 mm; beyond it the flats press at their edges, and the torque
// opposes the twist with the push at the centroid of the pressed strip (a third of its width in
// from the edge), h/2 - e / (3 theta) for an edge closure e.
TEST(PlanarLawTest, ATwistedSquareShaftMeetsItsFlatsAtTheEdgesAndIsTurnedBack) {
  const double clearance = 3e-6, h = 18e-3;
  PartSpec shaft = MakePart("shaft", Role::kInner, 20e-3, -21e-6, 0.0, 30e-3, h, 4);
  PartSpec hole = MakePart("hole", Role::kOuter, 20e-3, 0.0, 21e-6, 30e-3, h, 4);
  PlanarDiscretizer discretizer;
  auto uniform = [&](const PartSpec& part, double v) {
    SkinModelShape sms;
    sms.grid = discretizer.Discretize(part, Resolution{12, 8});
    sms.variation = Eigen::VectorXd::Constant(sms.grid.size(), v);
    return sms;
  };
  ModelSettings settings;
  settings.contact_stiffness = 1e8;  // 100 N/um
  PlanarContactAnalyzer analyzer;
  analyzer.Prepare(shaft, uniform(shaft, -clearance), hole, uniform(hole, 0.0), settings);
  PlanarGpsLaw law;
  law.Prepare(shaft, hole, settings);
  MatingPose pose;
  pose.depth = 30e-3;
  pose.offset = {1e-6, 0.0};  // resting 1 um towards +x: 2 um of play left on that side
  const double touch = (clearance - 1e-6) / (h / 2);
  ContactState contact;
  Wrench w;
  MatingMotion motion;
  // Within the play nothing touches: no push, no torque.
  pose.angle = motion.angle = 0.9 * touch;
  analyzer.Evaluate(pose, &contact);
  law.Evaluate(contact, motion, &w);
  EXPECT_EQ(contact.penetration, 0.0);
  EXPECT_EQ(w.torque.y(), 0.0);
  // Beyond it the +x flat's edge closes by e = h/2 theta - 2 um; the push k e acts a third of the
  // pressed width in, e / (3 theta), from the edge.
  for (const double theta : {1.1 * touch, 1.5 * touch, -1.5 * touch}) {
    pose.angle = motion.angle = theta;
    analyzer.Evaluate(pose, &contact);
    law.Evaluate(contact, motion, &w);
    const double e = h / 2 * std::abs(theta) - 2e-6;
    EXPECT_NEAR(contact.penetration, e, 1e-15) << theta;
    EXPECT_NEAR(w.force.x(), -1e8 * e, 1e-6) << theta;
    const double lever = h / 2 - e / (3.0 * std::abs(theta));
    EXPECT_NEAR(w.torque.y(), -std::copysign(lever * 1e8 * e, theta), 1e-9) << theta;
  }
}

}  // namespace
}  // namespace fitfeel::planar
