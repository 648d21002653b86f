#include "devices/simulated/simulated_device.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel::simulated {
namespace {

constexpr double kPeriod = 1e-3;

// The paper's robot: 10 mm/s from 2 mm before the entrance.
Settings Robot() {
  Settings s;
  s.speed = 10e-3;
  s.start_offset = 2e-3;
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
  device.Configure(Robot());
  device.Start(kPeriod);
  for (int n : {0, 1, 137, 5000}) {
    SimulatedDevice d;
    d.Configure(Robot());
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
  Settings settings = Robot();
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

// A trajectory: no force moves the part across the axis (the load and what the part does under it
// are the scene's part motion, framework side).
TEST(SimulatedRobotTest, MovesNothingRadially) {
  SimulatedDevice device;
  device.Configure(Robot());
  device.Start(kPeriod);
  const DeviceState inside = Drive(device, 400, [](const DeviceState&) {
    Wrench w;
    w.force = Eigen::Vector3d(3.0, -1.0, 50.0);
    return w;
  });
  EXPECT_EQ(inside.position.x(), 0.0);
  EXPECT_EQ(inside.position.z(), 0.0);
  EXPECT_EQ(inside.velocity.x(), 0.0);
  EXPECT_EQ(inside.velocity.z(), 0.0);
  EXPECT_TRUE(std::isinf(device.spec().max_stiffness));
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

Settings Rotor(double angular_speed, double swing) {
  Settings s;
  s.mode = Settings::Mode::kConstantRotation;
  s.angular_speed = angular_speed;
  s.swing = swing;
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
    d.Configure(Rotor(omega, 0.0));
    d.Start(kPeriod);
    EXPECT_EQ(d.angular_reach(2.0), 2.0 * omega);  // its whole travel
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
    // Held at the entrance (captive), from the first tick.
    EXPECT_EQ(s.position, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.velocity, Eigen::Vector3d::Zero());
  }
}

TEST(SimulatedRotorTest, OscillatesBetweenPlusAndMinusTheSwingAtConstantSpeed) {
  const double omega = 15.0 * M_PI / 180.0, beta = 15.0 * M_PI / 180.0;
  SimulatedDevice d;
  d.Configure(Rotor(omega, beta));
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
  // What it reports it turns by at most, for the prepare (ModelSettings::angular_reach).
  EXPECT_EQ(d.angular_reach(8.0), beta);
  EXPECT_EQ(reversals, 4);
}

TEST(SimulatedDeviceTest, RefusesSettingsOutOfRange) {
  SimulatedDevice device;
  Settings s = Robot();
  s.speed = 0.0;
  EXPECT_THROW(device.Configure(s), UserError);
  s = Robot();
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
  EXPECT_THROW(device.Configure(Rotor(0.0, 0.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(-1.0, 0.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(1.0, -0.1)), UserError);
  EXPECT_THROW(device.Configure(Rotor(1.0, 4.0)), UserError);
  EXPECT_THROW(device.Configure(Rotor(std::nan(""), 0.1)), UserError);
  EXPECT_NO_THROW(device.Configure(Rotor(1.0, M_PI)));
}

}  // namespace
}  // namespace fitfeel::simulated
