#include <cmath>
#include <string>

#include "devices/simulated/simulated_device.h"
#include "framework/core/config_node.h"
#include "framework/core/error.h"
#include "framework/device/device.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel::simulated {
namespace {

ConfigNode Node(const std::string& yaml) { return ConfigNode::Parse(yaml, "scene.yaml", "device"); }

std::string ErrorOf(const std::string& yaml) {
  SimulatedDevice device;
  try {
    device.Configure(Node(yaml));
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SimulatedConfigTest, ReadsTheRobotWithUnits) {
  SimulatedDevice device;
  device.Configure(Node("plugin: fitfeel.device.simulated\nspeed: 10 mm/s\nstart_offset: 5 mm\n"));
  const Settings& s = device.settings();
  EXPECT_EQ(s.mode, Settings::Mode::kConstantSpeed);
  EXPECT_DOUBLE_EQ(s.speed, 0.01);
  EXPECT_DOUBLE_EQ(s.start_offset, 5e-3);
}

// Any mode renders as a named device would: the table's limits, the simulated trajectory.
TEST(SimulatedConfigTest, RendersAsANamedDevice) {
  SimulatedDevice device;
  device.Configure(
      Node("plugin: fitfeel.device.simulated\nspeed: 10 mm/s\nmodel: Geomagic Touch\n"));
  device.Start(1e-3);
  const DeviceSpec spec = device.spec();
  EXPECT_DOUBLE_EQ(spec.max_force, 3.3);
  EXPECT_DOUBLE_EQ(spec.max_continuous_force, 0.88);
  EXPECT_DOUBLE_EQ(spec.max_stiffness, 400.0);
  EXPECT_DOUBLE_EQ(spec.damping, 4.0);
  EXPECT_EQ(spec.model, "simulated robot (constant speed, constant radial load) as Touch");
  device.Stop();
  const std::string error =
      ErrorOf("plugin: fitfeel.device.simulated\nspeed: 10 mm/s\nmodel: falcon\n");
  EXPECT_NE(error.find("scene.yaml:3:8: device.model: expected a haptic device model ('PHANTOM "
                       "Desktop', 'PHANTOM Omni', 'Touch', 'PHANTOM Premium 1.0', 'PHANTOM "
                       "Premium 1.5', 'PHANTOM Premium 1.5 High Force', 'PHANTOM Premium 3.0')"),
            std::string::npos)
      << error;
}

// Any mode hands the force mapping it names over in its spec, as a hardware device's spec would.
TEST(SimulatedConfigTest, HandsTheForceMappingOverInItsSpec) {
  for (const char* mode :
       {"speed: 10 mm/s\n", "mode: constant_rotation\nangular_speed: 1 rad/s\n",
        "mode: scripted\nhand: {mass: 500 g, stiffness: 0.5 N/mm, damping: 30 N*s/m}\n"
        "waypoints:\n  - {time: 0 s, position: [0 mm, 0 mm, 0 mm]}\n"}) {
    SimulatedDevice device;
    device.Configure(Node(std::string("plugin: fitfeel.device.simulated\nforce_mapping: "
                                      "perceptual\n") +
                          mode));
    device.Start(1e-3);
    EXPECT_EQ(device.spec().force_mapping, ForceMappingKind::kPerceptual) << mode;
    device.Stop();
  }
  SimulatedDevice touch;
  touch.Configure(
      Node("plugin: fitfeel.device.simulated\nspeed: 10 mm/s\nmodel: premium-1.5\nforce_mapping: "
           "perceptual\n"));
  touch.Start(1e-3);
  EXPECT_EQ(touch.spec().force_mapping, ForceMappingKind::kPerceptual);
  EXPECT_DOUBLE_EQ(touch.spec().max_force, 8.5);
  touch.Stop();
  SimulatedDevice plain;
  plain.Configure(Node("plugin: fitfeel.device.simulated\nspeed: 10 mm/s\n"));
  EXPECT_EQ(plain.spec().force_mapping, ForceMappingKind::kLinear);
  const std::string error =
      ErrorOf("plugin: fitfeel.device.simulated\nspeed: 10 mm/s\nforce_mapping: log\n");
  EXPECT_NE(error.find("scene.yaml:3:16: device.force_mapping: expected one of"), std::string::npos)
      << error;
}

TEST(SimulatedConfigTest, ReadsAScriptedHand) {
  SimulatedDevice device;
  device.Configure(Node(R"(mode: scripted
hand: {mass: 500 g, stiffness: 0.5 N/mm, damping: 30 N*s/m}
waypoints:
  - {time: 0 s, position: [0 mm, -10 mm, 0 mm]}
  - {time: 2 s, position: [0 mm, 15 mm, 0 mm]}
)"));
  const Settings& s = device.settings();
  EXPECT_EQ(s.mode, Settings::Mode::kScripted);
  EXPECT_DOUBLE_EQ(s.hand_mass, 0.5);
  EXPECT_DOUBLE_EQ(s.hand_stiffness, 500.0);
  ASSERT_EQ(s.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(s.waypoints[1].position.y(), 15e-3);
  EXPECT_DOUBLE_EQ(s.waypoints[1].time, 2.0);
  EXPECT_EQ(s.tremor_amplitude, 0.0);

  SimulatedDevice shaky;
  shaky.Configure(Node(R"(mode: scripted
hand: {mass: 500 g, stiffness: 2 N/mm, tremor: true, aim_error: [0.3 mm, -1 mm]}
waypoints: [{time: 0 s, position: [0 mm, -10 mm, 0 mm]}]
)"));
  EXPECT_DOUBLE_EQ(shaky.settings().tremor_amplitude, 0.1e-3);
  EXPECT_DOUBLE_EQ(shaky.settings().tremor_frequency, 10.0);
  EXPECT_DOUBLE_EQ(shaky.settings().aim_error.y(), -1e-3);
  SimulatedDevice custom;
  custom.Configure(Node(R"(mode: scripted
hand: {mass: 500 g, stiffness: 2 N/mm, tremor: {amplitude: 50 um, frequency: 8 Hz}}
waypoints: [{time: 0 s, position: [0 mm, -10 mm, 0 mm]}]
)"));
  EXPECT_DOUBLE_EQ(custom.settings().tremor_amplitude, 50e-6);
  EXPECT_DOUBLE_EQ(custom.settings().tremor_frequency, 8.0);
  SimulatedDevice bad;
  EXPECT_THROW(bad.Configure(Node(R"(mode: scripted
hand: {mass: 500 g, stiffness: 2 N/mm, aim_error: [1 mm]}
waypoints: [{time: 0 s, position: [0 mm, -10 mm, 0 mm]}]
)")),
               ScenarioError);
}

// A held tilt: the orientation the device reports carries it (MatingPoseOf reads it back), the
// prepare learns it from held_tilt; beyond the hand-over's 1 degree, or changing between a hand's
// waypoints, it is refused at its key.
TEST(SimulatedConfigTest, HoldsThePartTilted) {
  SimulatedDevice robot;
  robot.Configure(Node("speed: 10 mm/s\ntilt: [0.5 deg, -0.2 deg]\n"));
  ASSERT_TRUE(robot.held_tilt().has_value());
  EXPECT_NEAR(robot.held_tilt()->x(), 0.5 * M_PI / 180.0, 1e-15);
  EXPECT_NEAR(robot.held_tilt()->y(), -0.2 * M_PI / 180.0, 1e-15);
  robot.Start(1e-3);
  DeviceState state;
  robot.Read(0.0, &state);
  // The part's axis, +y turned by the rotation vector (0.5 deg, 0, -0.2 deg).
  const Eigen::Vector3d axis = state.orientation * Eigen::Vector3d::UnitY();
  EXPECT_NEAR(axis.z(), std::sin(0.5 * M_PI / 180.0), 1e-6);
  EXPECT_NEAR(axis.x(), std::sin(0.2 * M_PI / 180.0), 1e-6);
  SimulatedDevice straight;
  straight.Configure(Node("speed: 10 mm/s\n"));
  EXPECT_FALSE(straight.held_tilt().has_value());
  const std::string steep = ErrorOf("speed: 10 mm/s\ntilt: [2 deg, 0 deg]\n");
  EXPECT_NE(steep.find("device.tilt"), std::string::npos) << steep;
  const std::string turning = ErrorOf(R"(mode: scripted
hand: {mass: 500 g, stiffness: 2 N/mm}
waypoints:
  - {time: 0 s, position: [0 mm, -10 mm, 0 mm], tilt: [0.5 deg, 0 deg]}
  - {time: 1 s, position: [0 mm, 10 mm, 0 mm], tilt: [0.2 deg, 0 deg]}
)");
  EXPECT_NE(turning.find("the same tilt as the first waypoint's"), std::string::npos) << turning;
  EXPECT_NE(ErrorOf("mode: constant_rotation\nangular_speed: 1 rad/s\ntilt: [1 deg, 0 deg]\n"),
            "no error");
}

TEST(SimulatedConfigTest, ReadsARotaryDriveInDegrees) {
  SimulatedDevice device;
  device.Configure(Node("mode: constant_rotation\nangular_speed: 15 deg/s\nswing: 15 deg\n"));
  const Settings& s = device.settings();
  EXPECT_EQ(s.mode, Settings::Mode::kConstantRotation);
  EXPECT_NEAR(s.angular_speed, 15.0 * M_PI / 180.0, 1e-15);
  EXPECT_NEAR(s.swing, 15.0 * M_PI / 180.0, 1e-15);
  device.Configure(Node("mode: constant_rotation\nangular_speed: 2 rad/s\n"));
  EXPECT_DOUBLE_EQ(device.settings().angular_speed, 2.0);
  EXPECT_EQ(device.settings().swing, 0.0);  // continuous rotation
}

TEST(SimulatedConfigTest, RefusesBadKeysWithTheirPath) {
  EXPECT_NE(ErrorOf("mode: constant_rotation\nangular_speed: 15 mm/s").find("device.angular_speed"),
            std::string::npos);
  EXPECT_NE(ErrorOf("mode: constant_rotation\nangular_speed: 0 deg/s").find("device.angular_speed"),
            std::string::npos);
  EXPECT_NE(ErrorOf("mode: constant_rotation\nangular_speed: 1 rad/s\nspeed: 1 mm/s").find("speed"),
            std::string::npos);
  EXPECT_NE(ErrorOf("mode: constant_rotation\nangular_speed: 1 rad/s\nswing: 200 deg")
                .find("device.swing"),
            std::string::npos);
  EXPECT_NE(ErrorOf("mode: constant_rotation\nswing: 10 deg").find("angular_speed"),
            std::string::npos);
  EXPECT_NE(ErrorOf("speed: 10 mm").find("device.speed"), std::string::npos);
  EXPECT_NE(ErrorOf("speed: 10 mm/s\nradial_lod: 2 N").find("radial_lod"), std::string::npos);
  EXPECT_NE(ErrorOf("speed: -1 mm/s").find("device.speed"), std::string::npos);
  // The load acting on the part is the scene's, and the refusal says where it went.
  EXPECT_NE(ErrorOf("speed: 10 mm/s\nradial_load: 2 N").find("part_motion: {radial_load"),
            std::string::npos);
  EXPECT_NE(ErrorOf("mode: teleport\nspeed: 1 mm/s").find("device.mode"), std::string::npos);
  EXPECT_NE(ErrorOf("mode: scripted\nhand: {mass: 1 kg, stiffness: 1 N/mm}\nwaypoints:\n"
                    "  - {time: 1 s, position: [0 mm, 0 mm]}")
                .find("position"),
            std::string::npos);
  EXPECT_NE(ErrorOf("mode: scripted\nhand: {mass: 1 kg, stiffness: 1 N/mm}\nwaypoints:\n"
                    "  - {time: 1 s, position: [0 mm, 0 mm, 0 mm]}\n"
                    "  - {time: 1 s, position: [0 mm, 1 mm, 0 mm]}")
                .find("time"),
            std::string::npos);
  // The part's radial motion left the device: the old keys say where it went.
  const std::string moved = ErrorOf("speed: 10 mm/s\nradial: dynamic");
  EXPECT_NE(moved.find("device.radial"), std::string::npos) << moved;
  EXPECT_NE(moved.find("part_motion"), std::string::npos) << moved;
  const std::string damping = ErrorOf("speed: 10 mm/s\nradial_damping: 5 N*s/m");
  EXPECT_NE(damping.find("device.radial_damping"), std::string::npos) << damping;
  EXPECT_NE(damping.find("part_motion"), std::string::npos) << damping;
  EXPECT_NE(ErrorOf("speed: 10 mm/s").find("no error"), std::string::npos);
}

}  // namespace
}  // namespace fitfeel::simulated
