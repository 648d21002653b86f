#include "devices/simulated/simulated_device.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel::simulated {
namespace {

constexpr double kPeriod = 1e-3;

// The radially dynamic robot: most tests here are about its integration.
Settings Robot(double load, double damping = 0.0) {
  Settings s;
  s.speed = 10e-3;
  s.start_offset = 2e-3;
  s.radial_load = load;
  s.radial_damping = damping;
  s.radial = Settings::Radial::kDynamic;
  return s;
}

// Runs `ticks` ticks with a rendered force given by `force(state)`; returns the last state read.
template <typename F>
DeviceState Drive(SimulatedDevice& device, int ticks, F force) {
  DeviceState state;
  for (int k = 0; k < ticks; ++k) {
    device.Read(k * kPeriod, &state);
    device.Write(force(state));
  }
  device.Read(ticks * kPeriod, &state);
  return state;
}

Wrench NoForce(const DeviceState&) { return Wrench{}; }

TEST(SimulatedRobotTest, AxialPositionAfterNTicksIsExact) {
  SimulatedDevice device;
  device.Configure(Robot(0.0));
  device.Start(kPeriod);
  for (int n : {0, 1, 137, 5000}) {
    SimulatedDevice d;
    d.Configure(Robot(0.0));
    d.Start(kPeriod);
    const DeviceState s = Drive(d, n, NoForce);
    EXPECT_EQ(s.position.y(), -2e-3 + 10e-3 * (n * kPeriod)) << n;
    EXPECT_EQ(s.velocity.y(), 10e-3);
    // No weight: held on the axis whatever force is rendered.
    EXPECT_EQ(s.position.x(), 0.0);
    EXPECT_EQ(s.position.z(), 0.0);
  }
  const DeviceState pushed = Drive(device, 400, [](const DeviceState&) {
    Wrench w;
    w.force = Eigen::Vector3d(5.0, -50.0, 5.0);
    return w;
  });
  EXPECT_EQ(pushed.position, Eigen::Vector3d(0.0, -2e-3 + 10e-3 * 0.4, 0.0));
}

// A force-driven press: the ram advances until the resistance reaches stop_force, then holds.
TEST(SimulatedRobotTest, ForceDrivenPressStopsWhereTheResistanceReachesItsForce) {
  Settings settings = Robot(0.0);
  settings.stop_force = 99.5;
  SimulatedDevice device;
  device.Configure(settings);
  device.Start(kPeriod);
  // A wall 1 mm past the start resisting 1 N per um: 100 N at 100 um into it.
  auto wall = [](const DeviceState& s) {
    Wrench w;
    w.force.y() = -std::max(0.0, s.position.y() + 1e-3) * 1e6;
    return w;
  };
  const DeviceState held = Drive(device, 400, wall);
  EXPECT_NEAR(held.position.y(), -1e-3 + 100e-6, 1e-12);  // the first tick at 99.5 N or more
  EXPECT_EQ(held.velocity.y(), 0.0);
  EXPECT_EQ(Drive(device, 10, wall).position.y(), held.position.y());
  settings.stop_force = -1.0;
  EXPECT_THROW(device.Configure(settings), UserError);
}

TEST(SimulatedRobotTest, QuasiStaticRobotAsksToSettleItsWeightInsideAndMovesNoRadialMass) {
  Settings settings = Robot(2.0);
  settings.radial = Settings::Radial::kQuasiStatic;
  SimulatedDevice device;
  device.Configure(settings);
  device.Start(kPeriod);
  DeviceState state;
  device.Read(0.0, &state);
  EXPECT_EQ(state.settle_load, Eigen::Vector2d(0.0, 0.0));  // the robot carries it outside
  const DeviceState inside = Drive(device, 400, [](const DeviceState&) {
    Wrench w;
    w.force = Eigen::Vector3d(0.0, -1.0, 50.0);
    return w;
  });
  EXPECT_EQ(inside.settle_load, Eigen::Vector2d(0.0, -2.0));
  EXPECT_EQ(inside.position.x(), 0.0);
  EXPECT_EQ(inside.position.z(), 0.0);
}

TEST(SimulatedRobotTest, WeightActsOnlyInsideTheEntranceAsAFreeFallOfTheShaftsMass) {
  SimulatedDevice device;
  device.Configure(Robot(2.0));
  EXPECT_DOUBLE_EQ(device.mass(), 2.0 / kStandardGravity);
  device.Start(kPeriod);
  // 2 mm before the entrance at 10 mm/s: carried for 200 ticks.
  DeviceState s = Drive(device, 200, NoForce);
  EXPECT_EQ(s.position.z(), 0.0);
  EXPECT_EQ(s.position.y(), 0.0);
  // From tick 200 on, n steps of symplectic Euler under g fall g h^2 n (n + 1) / 2.
  SimulatedDevice falling;
  falling.Configure(Robot(2.0));
  falling.Start(kPeriod);
  const int n = 50;
  s = Drive(falling, 200 + n, NoForce);
  EXPECT_NEAR(s.position.z(), -kStandardGravity * kPeriod * kPeriod * n * (n + 1) / 2.0, 1e-15);
  EXPECT_NEAR(s.velocity.z(), -kStandardGravity * kPeriod * n, 1e-13);
  EXPECT_EQ(s.position.x(), 0.0);
}

// A radial contact spring below the part: F_z = -k (z - z0) when z < z0.
Wrench Floor(const DeviceState& s, double k, double z0) {
  Wrench w;
  if (s.position.z() < z0) w.force.z() = -k * (s.position.z() - z0);
  return w;
}

TEST(SimulatedRobotTest, SettlesOnASpringAtTheStaticEquilibrium) {
  const double load = 2.0, k = 2e5;  // 0.2 N/um, a quarter of the stability bound
  SimulatedDevice device;
  // Damping of 0.7 of critical for the part on that spring, so that it settles in ~10 ms.
  const double m = load / kStandardGravity;
  device.Configure(Robot(load, 2 * 0.7 * std::sqrt(k * m)));
  device.Start(kPeriod);
  const DeviceState s =
      Drive(device, 1200, [&](const DeviceState& st) { return Floor(st, k, 0.0); });
  EXPECT_NEAR(s.position.z(), -load / k, 1e-12);  // 10 um down
  EXPECT_NEAR(s.velocity.z(), 0.0, 1e-12);
}

TEST(SimulatedRobotTest, WithoutTheStiffnessAnExplicitContactIsStableOnlyBelowTheBound) {
  const double load = 2.0;
  SimulatedDevice probe;
  probe.Configure(Robot(load));
  probe.Start(kPeriod);
  const double bound = probe.ExplicitStabilityBound();
  EXPECT_TRUE(std::isinf(probe.spec().max_stiffness));
  EXPECT_NEAR(bound, 4.0 * (load / kStandardGravity) / (kPeriod * kPeriod), 1e-6);
  for (double factor : {0.9, 1.1}) {
    SimulatedDevice device;
    device.Configure(Robot(load));
    device.Start(kPeriod);
    const double k = factor * bound;
    // Bilateral spring, so that the oscillation cannot leave it.
    double min_z = 0.0, sum_z = 0.0;
    const int ticks = 3000;
    DeviceState state;
    for (int t = 0; t < ticks; ++t) {
      device.Read(t * kPeriod, &state);
      if (t >= 1200) {
        min_z = std::min(min_z, state.position.z());
        sum_z += state.position.z();
      }
      Wrench w;
      if (state.position.y() >= 0.0) w.force.z() = -k * state.position.z();
      device.Write(w);
    }
    if (factor < 1.0) {
      // Symplectic Euler: a bounded oscillation about the equilibrium -W/k. Starting at rest on
      // the axis, its invariant ellipse reaches W/k / sqrt(1 - k h^2 / 4m) below the equilibrium
      // (the discrete map's stretch, 3.2x at 0.9 of the bound), and never further.
      const double m = load / kStandardGravity;
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

TEST(SimulatedRobotTest, ASteelPressFitToldItsStiffnessSettlesWithinTicks) {
  // 3.665 N/nm (the Lame radial stiffness of the case study's joint): 4500 times the explicit
  // bound. Handed the stiffness, the part lands on the contact and rests at -W/k.
  const double load = 2.0, k = 3.665e9;
  SimulatedDevice device;
  device.Configure(Robot(load));
  device.Start(kPeriod);
  DeviceState state;
  double max_height = -1.0;
  for (int t = 0; t < 600; ++t) {
    device.Read(t * kPeriod, &state);
    // A floor 12 um below the axis: the part falls onto it after the entrance (tick 200).
    const double floor = -12e-6;
    Wrench w;
    const bool contact = state.position.z() < floor;
    if (contact) w.force.z() = -k * (state.position.z() - floor);
    device.SetEnvironmentStiffness(contact ? k : 0.0);
    device.Write(w);
    if (t > 220) max_height = std::max(max_height, state.position.z());
  }
  device.Read(600 * kPeriod, &state);
  EXPECT_NEAR(state.position.z(), -12e-6 - load / k, 1e-12);
  EXPECT_NEAR(state.velocity.z(), 0.0, 1e-9);
  EXPECT_LT(max_height, -12e-6 + 1e-9);  // never bounced off
}

TEST(SimulatedRobotTest, FollowsAMovingStiffContactWithoutLagForce) {
  // A bilateral contact whose anchor sinks at 2 um/s (as the energy-minimising axis does with
  // depth under interference): F = -k (z - a(t)). The part must follow it with F balancing the
  // weight, not lag it by a tick (which would cost k * 2 nm = 7 N here).
  const double load = 2.0, k = 3.665e9, rate = -2e-6;
  SimulatedDevice device;
  device.Configure(Robot(load));
  device.Start(kPeriod);
  DeviceState state;
  double last_force = 0.0;
  for (int t = 0; t < 800; ++t) {
    device.Read(t * kPeriod, &state);
    const double anchor = -5e-6 + rate * t * kPeriod;
    Wrench w;
    if (state.position.y() >= 0.0) w.force.z() = -k * (state.position.z() - anchor);
    device.SetEnvironmentStiffness(state.position.y() >= 0.0 ? k : 0.0);
    device.Write(w);
    last_force = w.force.z();
  }
  EXPECT_NEAR(last_force, load, 1e-3);
}

TEST(SimulatedRobotTest, OneFreeTickAfterContactDoesNotDropThePartIntoTheSurface) {
  // Resting on a stiff floor; at tick 400 the contact reports nothing for one tick (the part was
  // pushed a hair outside it). A free step would fall g h^2 = 9.8 um and come back with
  // k * 9.8 um = 36 kN; the remembered plane keeps it on the surface.
  const double load = 2.0, k = 3.665e9, floor = -12e-6;
  SimulatedDevice device;
  device.Configure(Robot(load));
  device.Start(kPeriod);
  DeviceState state;
  double after = 0.0;
  for (int t = 0; t < 410; ++t) {
    device.Read(t * kPeriod, &state);
    Wrench w;
    const bool contact = state.position.z() < floor && t != 400;
    if (contact) w.force.z() = -k * (state.position.z() - floor);
    device.SetEnvironmentStiffness(contact ? k : 0.0);
    device.Write(w);
    if (t > 400) after = std::max(after, std::abs(w.force.z()));
  }
  EXPECT_LT(after, 2.0 * load);
  EXPECT_GT(after, 0.5 * load);
  EXPECT_NEAR(state.position.z(), floor - load / k, 1e-11);
}

TEST(SimulatedHandTest, FollowsTheWaypointsAndYieldsToAForceByItsStiffness) {
  Settings s;
  s.mode = Settings::Mode::kScripted;
  s.hand_mass = 0.5;
  s.hand_stiffness = 500.0;
  s.hand_damping = 2 * std::sqrt(500.0 * 0.5);  // critically damped
  s.waypoints = {{0.0, {0.0, -5e-3, 0.0}}, {0.5, {0.0, 5e-3, 1e-3}}};
  SimulatedDevice device;
  device.Configure(s);
  device.Start(kPeriod);
  DeviceState state = Drive(device, 0, NoForce);
  EXPECT_EQ(state.position, Eigen::Vector3d(0.0, -5e-3, 0.0));
  // Half way along the 20 mm/s ramp: the damper acts on the velocity error, so the hand tracks
  // a ramp without steady lag once the start transient (time constant sqrt(m/k) = 32 ms) is gone.
  state = Drive(device, 250, NoForce);
  EXPECT_NEAR(state.position.y(), 0.0, 1e-5);
  EXPECT_NEAR(state.position.z(), 0.5e-3, 1e-6);
  EXPECT_NEAR(state.velocity.y(), 20e-3, 0.2e-3);
  // Long after the last waypoint it rests on it; a constant 1 N along -y then moves it by F / k.
  SimulatedDevice held;
  held.Configure(s);
  held.Start(kPeriod);
  state = Drive(held, 3000, NoForce);
  EXPECT_NEAR((state.position - Eigen::Vector3d(0.0, 5e-3, 1e-3)).norm(), 0.0, 1e-9);
  SimulatedDevice pushed;
  pushed.Configure(s);
  pushed.Start(kPeriod);
  state = Drive(pushed, 3000, [](const DeviceState&) {
    Wrench w;
    w.force.y() = -1.0;
    return w;
  });
  EXPECT_NEAR(state.position.y(), 5e-3 - 1.0 / 500.0, 1e-9);
  EXPECT_NEAR(state.velocity.norm(), 0.0, 1e-9);
}

// The hand's tremor passes through its own mass-spring-damper: the hand moves at the tremor's
// frequency with the steady-state gain |k + i b w| / |k - m w^2 + i b w| of the target's motion
// (within backward Euler's damping at w h = 0.063), circling about the aimed-at point.
TEST(SimulatedHandTest, TremorsAtItsFrequencyAroundTheAimedPoint) {
  Settings s;
  s.mode = Settings::Mode::kScripted;
  s.hand_mass = 0.5;
  s.hand_stiffness = 2000.0;
  s.hand_damping = 20.0;
  s.tremor_amplitude = 0.1e-3;
  s.tremor_frequency = 10.0;
  s.aim_error = Eigen::Vector2d(0.3e-3, -0.2e-3);
  s.waypoints = {{0.0, {0.0, -5e-3, 0.0}}};
  SimulatedDevice device;
  device.Configure(s);
  device.Start(kPeriod);
  double lo = 1.0, hi = -1.0, sum = 0.0;
  int crossings = 0;
  double previous = 0.0;
  const int settle = 2000;  // transients (time constant 2 m / b = 50 ms) gone
  const int n = 1000;       // then one second: ten tremor periods
  DeviceState state;
  for (int k = 0; k < settle + n; ++k) {
    device.Read(k * kPeriod, &state);
    device.Write(Wrench{});
    if (k < settle) continue;
    const int t = k - settle;
    const double x = state.position.x() - 0.3e-3;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    sum += state.position.z();
    if (t > 0 && (x > 0.0) != (previous > 0.0)) ++crossings;
    previous = x;
  }
  EXPECT_NEAR(crossings, 20, 1);  // 10 Hz
  const double w = 2 * M_PI * 10.0;
  const double gain = std::hypot(2000.0, 20.0 * w) / std::hypot(2000.0 - 0.5 * w * w, 20.0 * w);
  EXPECT_NEAR(0.5 * (hi - lo), gain * 0.1e-3, 0.1 * gain * 0.1e-3);
  // The circle's centre: the aimed-at point, offset by the aiming error (z starts at the
  // waypoint: its centre is one amplitude below).
  EXPECT_NEAR(sum / n, -0.2e-3 - 0.1e-3, 0.02e-3);
}

Settings Rotor(double angular_speed, double swing, double load) {
  Settings s;
  s.mode = Settings::Mode::kConstantRotation;
  s.angular_speed = angular_speed;
  s.swing = swing;
  s.radial_load = load;
  return s;
}

// The twist about y of the reported orientation (what the runtime's MatingPoseOf reads).
double TwistOf(const DeviceState& s) {
  return 2.0 * std::atan2(s.orientation.y(), s.orientation.w());
}

TEST(SimulatedRotorTest, TurnsAtTheAngularSpeedAboutTheAxisAtTheEntrance) {
  const double omega = 0.3;
  for (int n : {0, 1, 250, 4000, 30000}) {
    SimulatedDevice d;
    d.Configure(Rotor(omega, 0.0, 1000.0));
    d.Start(kPeriod);
    const DeviceState s = Drive(d, n, [](const DeviceState&) {
      Wrench w;
      w.force = Eigen::Vector3d(0.0, 0.0, 1000.0);
      w.torque = Eigen::Vector3d(0.0, -5.0, 0.0);  // a drive turns whatever the torque
      return w;
    });
    const double expected = std::remainder(omega * n * kPeriod, 2.0 * M_PI);
    EXPECT_NEAR(TwistOf(s), expected, 1e-12) << n;
    EXPECT_NEAR(s.orientation.norm(), 1.0, 1e-15);
    // Only a twist about y: the part's axis stays the mating axis (the hand-over's alignment).
    EXPECT_NEAR(s.orientation.toRotationMatrix()(1, 1), 1.0, 1e-15);
    EXPECT_EQ(s.angular_velocity, Eigen::Vector3d(0.0, omega, 0.0));
    // Held at the entrance (captive), settled by the stage under its load from the first tick.
    EXPECT_EQ(s.position, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.velocity, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.settle_load, Eigen::Vector2d(0.0, -1000.0));
  }
}

TEST(SimulatedRotorTest, OscillatesBetweenPlusAndMinusTheSwingAtConstantSpeed) {
  const double omega = 15.0 * M_PI / 180.0, beta = 15.0 * M_PI / 180.0;
  SimulatedDevice d;
  d.Configure(Rotor(omega, beta, 0.0));
  d.Start(kPeriod);
  // A full oscillation sweeps 4 beta: 4 s here. Over two of them the angle stays within +-beta,
  // reaches both ends, moves by omega * h each tick in the direction of the reported rate (but
  // at a reversal), and is back at 0 after each period.
  const int period_ticks = static_cast<int>(std::lround(4.0 * beta / omega / kPeriod));
  ASSERT_EQ(period_ticks, 4000);
  DeviceState s;
  double previous = 0.0, previous_rate = 0.0, lowest = 0.0, highest = 0.0;
  int reversals = 0;
  for (int k = 0; k <= 2 * period_ticks; ++k) {
    d.Read(k * kPeriod, &s);
    d.Write(Wrench{});
    const double angle = TwistOf(s);
    ASSERT_LE(std::abs(angle), beta + 1e-12) << k;
    EXPECT_EQ(std::abs(s.angular_velocity.y()), omega);
    lowest = std::min(lowest, angle);
    highest = std::max(highest, angle);
    if (k > 0) {
      if (s.angular_velocity.y() != previous_rate) {
        ++reversals;
      } else {
        EXPECT_NEAR(angle - previous, previous_rate * kPeriod, 1e-12) << k;
      }
    }
    if (k % period_ticks == 0) {
      EXPECT_NEAR(angle, 0.0, 1e-12) << k;
    }
    previous = angle;
    previous_rate = s.angular_velocity.y();
  }
  EXPECT_NEAR(highest, beta, 1e-12);
  EXPECT_NEAR(lowest, -beta, 1e-12);
  EXPECT_EQ(reversals, 4);
  EXPECT_EQ(s.settle_load, Eigen::Vector2d(0.0, 0.0));  // no load, nothing to settle
}

TEST(SimulatedDeviceTest, RefusesSettingsOutOfRange) {
  SimulatedDevice device;
  Settings s = Robot(2.0);
  s.speed = 0.0;
  EXPECT_THROW(device.Configure(s), UserError);
  s = Robot(-1.0);
  EXPECT_THROW(device.Configure(s), UserError);
  s = Robot(2.0);
  s.start_offset = std::nan("");
  EXPECT_THROW(device.Configure(s), UserError);
  s = Settings{};
  s.mode = Settings::Mode::kScripted;
  s.hand_mass = 1.0;
  s.hand_stiffness = 100.0;
  EXPECT_THROW(device.Configure(s), UserError);  // no waypoints
  s.waypoints = {{1.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d::Zero()}};
  EXPECT_THROW(device.Configure(s), UserError);  // not increasing
  s.waypoints = {{0.0, Eigen::Vector3d::Zero()}};
  s.hand_mass = 0.0;
  EXPECT_THROW(device.Configure(s), UserError);
  EXPECT_THROW(device.Configure(Rotor(0.0, 0.0, 0.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(-1.0, 0.0, 0.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(1.0, -0.1, 0.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(1.0, 4.0, 0.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(1.0, 0.1, -5.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(std::nan(""), 0.1, 0.0)), UserError);
  EXPECT_NO_THROW(device.Configure(Rotor(1.0, M_PI, 5.0)));
}

}  // namespace
}  // namespace fitfeel::simulated
