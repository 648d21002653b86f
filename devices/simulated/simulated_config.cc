// The scenario's `device` node for fitfeel.device.simulated, checked key by key with units.
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "devices/simulated/simulated_device.h"
#include "framework/core/config_node.h"
#include "framework/device/device_specs.h"

namespace fitfeel::simulated {
namespace {

double Optional(const ConfigNode& node, std::string_view key, Dimension dimension, double lo,
                double hi, double fallback) {
  const auto child = node.Find(key);
  return child ? child->AsQuantityIn(dimension, lo, hi) : fallback;
}

// The part's radial motion is the scene's, not the device's (framework/runtime/part_motion.h):
// keys of earlier scenario files are refused with where they went.
void RefuseMovedKeys(const ConfigNode& node) {
  if (const auto radial = node.Find("radial")) {
    radial->Fail(
        "no `radial` here: how the part moves across the axis is the scene's "
        "`part_motion: {radial: held | quasi_static | dynamic}`",
        radial->Describe());
  }
  if (const auto damping = node.Find("radial_damping")) {
    damping->Fail(
        "no `radial_damping` here: the part's radial damping is the scene's "
        "`part_motion: {damping: ...}`",
        damping->Describe());
  }
  if (const auto load = node.Find("radial_load")) {
    load->Fail(
        "no `radial_load` here: the load acting on the part across the axis is the scene's "
        "`part_motion: {radial_load: ...}`",
        load->Describe());
  }
}

// `tilt: [about x, about z]`, angles within 1 degree of the axis (kMaxTilt).
Eigen::Vector2d ParseTilt(const ConfigNode& node) {
  const auto xz = node.is_sequence() ? node.Items() : std::vector<ConfigNode>{};
  if (xz.size() != 2) {
    node.Fail("[angle about x, angle about z] with units, e.g. [0.5 deg, 0 deg]", node.Describe());
  }
  Eigen::Vector2d tilt;
  for (int i = 0; i < 2; ++i) tilt[i] = xz[i].AsQuantityIn(Dimension::kAngle, -kMaxTilt, kMaxTilt);
  if (tilt.norm() > kMaxTilt) {
    node.Fail(
        "a tilt within 1 deg of the mating axis (the positioning stage hands over no "
        "part tilted more)",
        node.Describe());
  }
  return tilt;
}

}  // namespace

void SimulatedDevice::DoConfigure(const ConfigNode& node) {
  Settings s;
  const auto mode = node.Find("mode");
  const std::string name =
      mode ? mode->AsOneOf({"constant_speed", "constant_rotation", "scripted"}) : "constant_speed";
  RefuseMovedKeys(node);
  // Any mode may render as a named haptic device would: its force limits and stiffness budget.
  if (std::optional<ConfigNode> model = node.Find("model")) {
    const std::string given = model->AsString();
    const std::optional<DeviceSpec> spec = FindDeviceSpec(given);
    if (!spec)
      model->Fail("a haptic device model (" + KnownDeviceModels() + ")", model->Describe());
    s.device_model = spec->model;
  }
  // The force mapping the run renders with, reported in the device's spec as a hardware device's
  // spec would (framework/safety/force_mapping.h); the scenario's `safety` section may override it.
  if (std::optional<ConfigNode> mapping = node.Find("force_mapping")) {
    s.force_mapping = mapping->AsOneOf({"linear", "perceptual"}) == "perceptual"
                          ? ForceMappingKind::kPerceptual
                          : ForceMappingKind::kLinear;
  }
  if (name == "constant_speed") {
    node.ExpectOnlyKeys({"plugin", "mode", "model", "force_mapping", "speed", "start_offset",
                         "stop_force", "tilt"});
    if (std::optional<ConfigNode> tilt = node.Find("tilt")) s.tilt = ParseTilt(*tilt);
    s.mode = Settings::Mode::kConstantSpeed;
    // Upper bounds: faster than 1 m/s is no assembly; more than 10 kN no part a hand or a small
    // robot holds; 1 m of approach is the size of a workcell.
    s.speed = node.Child("speed").AsQuantityIn(Dimension::kVelocity, 0.0, 1.0, false);
    s.start_offset = Optional(node, "start_offset", Dimension::kLength, 0.0, 1.0, 1e-3);
    // A press's force monitoring: 1 MN is beyond any bench press.
    s.stop_force = Optional(node, "stop_force", Dimension::kForce, 0.0, 1e6, 0.0);
  } else if (name == "constant_rotation") {
    node.ExpectOnlyKeys({"plugin", "mode", "model", "force_mapping", "angular_speed", "swing"});
    s.mode = Settings::Mode::kConstantRotation;
    // 100 rad/s is far beyond a plain bearing's oscillation; a swing beyond half a turn each way
    // is a rotation (0 or no key: continuous).
    s.angular_speed =
        node.Child("angular_speed").AsQuantityIn(Dimension::kAngularVelocity, 0.0, 100.0, false);
    s.swing = Optional(node, "swing", Dimension::kAngle, 0.0, M_PI + 1e-9, 0.0);
  } else {
    node.ExpectOnlyKeys({"plugin", "mode", "model", "force_mapping", "hand", "waypoints"});
    s.mode = Settings::Mode::kScripted;
    const ConfigNode hand = node.Child("hand");
    hand.ExpectOnlyKeys({"mass", "stiffness", "damping", "tremor", "aim_error", "tilt_stiffness"});
    // Fingers and wrist about the grip: a relaxed human wrist measures about 1 N*m/rad, a
    // co-contracted one several times that; 1e4 N*m/rad is a fixture, not a hand.
    if (const auto stiffness = hand.Find("tilt_stiffness")) {
      s.tilt_stiffness = stiffness->AsQuantityIn(Dimension::kAngularStiffness, 0.0, 1e4, false);
    }
    if (const auto tremor = hand.Find("tremor")) {
      // Physiological tremor of the outstretched hand: 8-12 Hz, displacement amplitudes of the
      // order of 0.1 mm (Elble & Koller, Tremor, 1990); `tremor: true` takes 0.1 mm at 10 Hz.
      s.tremor_amplitude = 0.1e-3;
      s.tremor_frequency = 10.0;
      if (tremor->is_map()) {
        tremor->ExpectOnlyKeys({"amplitude", "frequency"});
        s.tremor_amplitude =
            Optional(*tremor, "amplitude", Dimension::kLength, 0.0, 10e-3, s.tremor_amplitude);
        s.tremor_frequency =
            Optional(*tremor, "frequency", Dimension::kFrequency, 0.1, 100.0, s.tremor_frequency);
      } else if (!tremor->AsBool()) {
        s.tremor_amplitude = 0.0;
      }
    }
    if (const auto aim = hand.Find("aim_error")) {
      const auto xz = aim->is_sequence() ? aim->Items() : std::vector<ConfigNode>{};
      if (xz.size() != 2) aim->Fail("[x, z] with units, e.g. [0.3 mm, 0 mm]", aim->Describe());
      for (int i = 0; i < 2; ++i)
        s.aim_error[i] = xz[i].AsQuantityIn(Dimension::kLength, -0.1, 0.1);
    }
    s.hand_mass = hand.Child("mass").AsQuantityIn(Dimension::kMass, 0.0, 1e3, false);
    s.hand_stiffness = hand.Child("stiffness").AsQuantityIn(Dimension::kStiffness, 0.0, 1e8, false);
    s.hand_damping = Optional(hand, "damping", Dimension::kDamping, 0.0, 1e6, 0.0);
    const ConfigNode list = node.Child("waypoints");
    if (!list.is_sequence() || list.Items().empty()) {
      list.Fail("a list of waypoints {time, position}", list.Describe());
    }
    for (const ConfigNode& item : list.Items()) {
      item.ExpectOnlyKeys({"time", "position", "angle", "tilt"});
      Waypoint w;
      w.time = item.Child("time").AsQuantityIn(Dimension::kTime, 0.0, 1e5);
      if (!s.waypoints.empty() && !(w.time > s.waypoints.back().time)) {
        item.Child("time").Fail("a time after the previous waypoint's",
                                item.Child("time").Describe());
      }
      const ConfigNode position = item.Child("position");
      const auto xyz = position.is_sequence() ? position.Items() : std::vector<ConfigNode>{};
      if (xyz.size() != 3)
        position.Fail("[x, y, z] with units, e.g. [0 mm, -5 mm, 0 mm]", position.Describe());
      for (int i = 0; i < 3; ++i)
        w.position[i] = xyz[i].AsQuantityIn(Dimension::kLength, -10.0, 10.0);
      // Twenty turns at most: fingers running a nut down a bolt, regripping between turns.
      if (std::optional<ConfigNode> angle = item.Find("angle")) {
        w.angle = angle->AsQuantityIn(Dimension::kAngle, -kMaxWaypointAngle, kMaxWaypointAngle);
      }
      // One tilt for the whole run: the contact is prepared for it (Device::held_tilt).
      const Eigen::Vector2d tilt =
          item.Find("tilt") ? ParseTilt(item.Child("tilt")) : Eigen::Vector2d::Zero();
      if (!s.waypoints.empty() && tilt != s.tilt) {
        const ConfigNode where = item.Find("tilt") ? item.Child("tilt") : item;
        where.Fail(
            "the same tilt as the first waypoint's (the part is held at one tilt for the "
            "whole run; a hand that turns the part is not modelled)",
            where.Describe());
      }
      s.tilt = tilt;
      s.waypoints.push_back(w);
    }
  }
  Configure(s);
}

}  // namespace fitfeel::simulated
