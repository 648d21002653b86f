// The moving part's radial motion (framework/runtime/part_motion.h), driven by the paper's robot
// as a load source: 10 mm/s from 2 mm before the entrance, its weight acting once inside.
#include "framework/runtime/part_motion.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "framework/core/error.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

constexpr double kPeriod = 1e-3;

// The robot's state at tick t: on the axis, 2 mm before the entrance at t = 0, at 10 mm/s.
DeviceState RobotAt(int t) {
  DeviceState s;
  s.time = t * kPeriod;
  s.position = Eigen::Vector3d(0.0, -2e-3 + 10e-3 * s.time, 0.0);
  s.velocity = Eigen::Vector3d(0.0, 10e-3, 0.0);
  return s;
}

// A run of the part: each tick places it, asks `contact` for the rendered wrench and the stiffness
// at the part, and steps. Returns the part as placed at tick `ticks`.
struct Contact {
  Wrench wrench;
  ContactFeedback feedback;
};
// The part carries `load` (N, the scene's part_motion.radial_load) along -z once inside.
PartState Drive(const PartMotion& unloaded, double load, int ticks,
                const std::function<Contact(int, const PartState&)>& contact) {
  PartMotionSettings settings = unloaded.settings();
  settings.radial_load = load;
  const PartMotion motion(settings, kPeriod);
  PartMotionState state = motion.MakeState();
  PartState part;
  for (int t = 0; t < ticks; ++t) {
    const DeviceState device = RobotAt(t);
    motion.Place(device, state, &part);
    const Contact c = contact(t, part);
    motion.Step(device, c.wrench, c.feedback, &state);
  }
  motion.Place(RobotAt(ticks), state, &part);
  return part;
}

Contact Free(int, const PartState&) { return Contact{}; }

PartMotion Dynamic(double damping = 0.0) {
  PartMotionSettings settings;
  settings.radial = RadialMotion::kDynamic;
  settings.damping = damping;
  return PartMotion(settings, kPeriod);
}

TEST(PartMotionTest, HeldAndQuasiStaticLeaveThePartWhereTheDeviceSaysAndOnlyOneSettles) {
  PartMotionSettings settings;
  const DeviceState inside = RobotAt(400);
  for (RadialMotion radial : {RadialMotion::kHeld, RadialMotion::kQuasiStatic}) {
    settings.radial = radial;
    const PartMotion motion(settings, kPeriod);
    const PartState part = Drive(motion, 2.0, 400, [](int, const PartState&) {
      Contact c;
      c.wrench.force = Eigen::Vector3d(3.0, -1.0, 50.0);
      c.feedback.stiffness = 1e9;
      return c;
    });
    EXPECT_EQ(part.position, inside.position);
    EXPECT_EQ(part.velocity, inside.velocity);
    // The stage settles the part only in quasi-static motion; held, the holder takes the load.
    EXPECT_EQ(part.settle_load, radial == RadialMotion::kHeld ? Eigen::Vector2d(0.0, 0.0)
                                                              : Eigen::Vector2d(0.0, -2.0));
  }
}

TEST(PartMotionTest, WeightActsOnlyInsideTheEntranceAsAFreeFallOfTheShaftsMass) {
  PartMotionSettings weighed;
  weighed.radial_load = 2.0;
  const PartMotion weight(weighed, kPeriod);
  EXPECT_DOUBLE_EQ(weight.MassAt(RobotAt(300)), 2.0 / kStandardGravity);
  EXPECT_EQ(weight.MassAt(RobotAt(0)), 0.0);
  const PartMotion motion = Dynamic();
  // 2 mm before the entrance at 10 mm/s: carried for 200 ticks.
  PartState s = Drive(motion, 2.0, 200, Free);
  EXPECT_EQ(s.position.z(), 0.0);
  EXPECT_EQ(s.position.y(), 0.0);
  EXPECT_EQ(s.settle_load, Eigen::Vector2d(0.0, 0.0));  // nothing for the stage to settle: it floats
  // From tick 200 on, n steps of symplectic Euler under g fall g h^2 n (n + 1) / 2.
  const int n = 50;
  s = Drive(motion, 2.0, 200 + n, Free);
  EXPECT_NEAR(s.position.z(), -kStandardGravity * kPeriod * kPeriod * n * (n + 1) / 2.0, 1e-15);
  EXPECT_NEAR(s.velocity.z(), -kStandardGravity * kPeriod * n, 1e-13);
  EXPECT_EQ(s.position.x(), 0.0);
  EXPECT_EQ(s.position.y(), RobotAt(200 + n).position.y());  // axially the device's
}

// A radial contact spring below the part: F_z = -k (z - z0) when z < z0.
Contact Floor(const PartState& s, double k, double z0, bool tell_stiffness) {
  Contact c;
  const bool touching = s.position.z() < z0;
  if (touching) c.wrench.force.z() = -k * (s.position.z() - z0);
  if (tell_stiffness && touching) c.feedback.stiffness = k;
  return c;
}

TEST(PartMotionTest, SettlesOnASpringAtTheStaticEquilibrium) {
  const double load = 2.0, k = 2e5;  // 0.2 N/um, a quarter of the stability bound
  // Damping of 0.7 of critical for the part on that spring, so that it settles in ~10 ms.
  const double m = load / kStandardGravity;
  const PartMotion motion = Dynamic(2 * 0.7 * std::sqrt(k * m));
  const PartState s = Drive(
      motion, load, 1200, [&](int, const PartState& part) { return Floor(part, k, 0.0, false); });
  EXPECT_NEAR(s.position.z(), -load / k, 1e-12);  // 10 um down
  EXPECT_NEAR(s.velocity.z(), 0.0, 1e-12);
}

TEST(PartMotionTest, WithoutTheStiffnessAnExplicitContactIsStableOnlyBelowTheBound) {
  const double load = 2.0, m = load / kStandardGravity;
  const PartMotion motion = Dynamic();
  const double bound = motion.ExplicitStabilityBound(m);
  EXPECT_NEAR(bound, 4.0 * m / (kPeriod * kPeriod), 1e-6);
  EXPECT_TRUE(std::isinf(motion.ExplicitStabilityBound(0.0)));
  for (double factor : {0.9, 1.1}) {
    const double k = factor * bound;
    // Bilateral spring, so that the oscillation cannot leave it.
    double min_z = 0.0, sum_z = 0.0;
    const int ticks = 3000;
    Drive(motion, load, ticks, [&](int t, const PartState& part) {
      if (t >= 1200) {
        min_z = std::min(min_z, part.position.z());
        sum_z += part.position.z();
      }
      Contact c;
      if (part.position.y() >= 0.0) c.wrench.force.z() = -k * part.position.z();
      return c;
    });
    if (factor < 1.0) {
      // Symplectic Euler: a bounded oscillation about the equilibrium -W/k. Starting at rest on
      // the axis, its invariant ellipse reaches W/k / sqrt(1 - k h^2 / 4m) below the equilibrium
      // (the discrete map's stretch, 3.2x at 0.9 of the bound), and never further.
      const double reach =
          (load / k) * (1.0 + 1.0 / std::sqrt(1.0 - k * kPeriod * kPeriod / (4 * m)));
      EXPECT_GT(min_z, -1.01 * reach);
      EXPECT_LT(min_z, -0.9 * reach);
      EXPECT_NEAR(sum_z / (ticks - 1200), -load / k, 0.2 * load / k);
    } else {
      EXPECT_LT(min_z, -1e3 * load / k);  // grows without bound
    }
  }
}

TEST(PartMotionTest, ASteelPressFitToldItsStiffnessSettlesWithinTicks) {
  // 3.665 N/nm (the Lame radial stiffness of the case study's joint): 4500 times the explicit
  // bound. Told the stiffness, the part lands on the contact and rests at -W/k.
  const double load = 2.0, k = 3.665e9, floor = -12e-6;
  const PartMotion motion = Dynamic();
  double max_height = -1.0;
  const PartState s = Drive(motion, load, 600, [&](int t, const PartState& part) {
    if (t > 220) max_height = std::max(max_height, part.position.z());
    return Floor(part, k, floor, true);  // the part falls onto it after the entrance (tick 200)
  });
  EXPECT_NEAR(s.position.z(), floor - load / k, 1e-12);
  EXPECT_NEAR(s.velocity.z(), 0.0, 1e-9);
  EXPECT_LT(max_height, floor + 1e-9);  // never bounced off
}

TEST(PartMotionTest, FollowsAMovingStiffContactWithoutLagForce) {
  // A bilateral contact whose anchor sinks at 2 um/s (as the energy-minimising axis does with
  // depth under interference): F = -k (z - a(t)). The part must follow it with F balancing the
  // weight, not lag it by a tick (which would cost k * 2 nm = 7 N here).
  const double load = 2.0, k = 3.665e9, rate = -2e-6;
  const PartMotion motion = Dynamic();
  double last_force = 0.0;
  Drive(motion, load, 800, [&](int t, const PartState& part) {
    const double anchor = -5e-6 + rate * t * kPeriod;
    Contact c;
    if (part.position.y() >= 0.0) {
      c.wrench.force.z() = -k * (part.position.z() - anchor);
      c.feedback.stiffness = k;
    }
    last_force = c.wrench.force.z();
    return c;
  });
  EXPECT_NEAR(last_force, load, 1e-3);
}

TEST(PartMotionTest, OneFreeTickAfterContactDoesNotDropThePartIntoTheSurface) {
  // Resting on a stiff floor; at tick 400 the contact reports nothing for one tick (the part was
  // pushed a hair outside it). A free step would fall g h^2 = 9.8 um and come back with
  // k * 9.8 um = 36 kN; the remembered plane keeps it on the surface.
  const double load = 2.0, k = 3.665e9, floor = -12e-6;
  const PartMotion motion = Dynamic();
  double after = 0.0;
  const PartState s = Drive(motion, load, 410, [&](int t, const PartState& part) {
    Contact c = t == 400 ? Contact{} : Floor(part, k, floor, true);
    if (t > 400) after = std::max(after, std::abs(c.wrench.force.z()));
    return c;
  });
  EXPECT_LT(after, 2.0 * load);
  EXPECT_GT(after, 0.5 * load);
  EXPECT_NEAR(s.position.z(), floor - load / k, 1e-11);
}

TEST(PartMotionTest, AFreeWayReportedByTheStageIsMetAsASurface) {
  // Resting on a stiff floor, which then drops by 1 um: the stage reports the part free with that
  // much free way straight down. A free step would fall 9.8 um; the part meets the surface.
  const double load = 2.0, k = 3.665e9, floor = -12e-6, lower = floor - 1e-6;
  const PartMotion motion = Dynamic();
  const PartState s = Drive(motion, load, 420, [&](int t, const PartState& part) {
    if (t < 400) return Floor(part, k, floor, true);
    Contact c;
    c.feedback.gap = std::max(0.0, part.position.z() - lower);
    c.feedback.gap_direction = Eigen::Vector2d(0.0, -1.0);
    return c;
  });
  EXPECT_LT(s.position.z(), floor - 0.5e-6);   // it went down to the new surface
  EXPECT_GT(s.position.z(), lower - 0.05e-6);  // and not through it
}

TEST(PartMotionTest, RefusesAPeriodOrDampingOutOfRange) {
  PartMotionSettings settings;
  EXPECT_THROW(PartMotion(settings, 0.0), UserError);
  EXPECT_THROW(PartMotion(settings, std::nan("")), UserError);
  settings.damping = -1.0;
  EXPECT_THROW(PartMotion(settings, kPeriod), UserError);
  settings.damping = 10.0;
  EXPECT_NO_THROW(PartMotion(settings, kPeriod));
}

}  // namespace
}  // namespace fitfeel
