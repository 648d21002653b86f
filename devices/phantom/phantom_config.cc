// Scenario-facing part of the Phantom device.
#include "devices/phantom/phantom_device.h"
#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel::phantom {
namespace {

Eigen::Vector3d Point(const ConfigNode& node) {
  const auto xyz = node.is_sequence() ? node.Items() : std::vector<ConfigNode>{};
  if (xyz.size() != 3) node.Fail("[x, y, z] with units, e.g. [0 mm, 0 mm, -20 mm]", node.Describe());
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) p[i] = xyz[i].AsQuantityIn(Dimension::kLength, -1.0, 1.0);
  return p;
}

// [x, -z, y]: scene axis i is the named device axis, signed.
Eigen::Matrix3d Axes(const ConfigNode& node) {
  const char* expected = "three signed device axes naming a rotation, e.g. [x, -z, y]";
  const auto items = node.is_sequence() ? node.Items() : std::vector<ConfigNode>{};
  if (items.size() != 3) node.Fail(expected, node.Describe());
  Eigen::Matrix3d axes = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const std::string name = items[i].AsOneOf({"x", "y", "z", "-x", "-y", "-z", "+x", "+y", "+z"});
    const double sign = name[0] == '-' ? -1.0 : 1.0;
    axes(i, name.back() - 'x') = sign;
  }
  if (!(axes * axes.transpose()).isIdentity(1e-12) || axes.determinant() < 0.0) {
    node.Fail(expected + std::string(" (each axis once, right-handed)"), node.Describe());
  }
  return axes;
}

}  // namespace

void PhantomDevice::DoConfigure(const ConfigNode& node) {
  node.ExpectOnlyKeys({"plugin", "model", "spec", "name", "auto_calibrate", "calibration_timeout",
                       "frame", "faults", "rate_tolerance"});
  PhantomSettings settings;
  if (auto n = node.Find("model")) {
    settings.model = n->AsString();
    if (!FindDeviceSpec(settings.model)) n->Fail("a known device model", n->Describe());
  }
  if (auto n = node.Find("spec")) {
    const DeviceSpec base =
        settings.model.empty() ? DeviceSpec{} : LookupDeviceSpec(settings.model);
    settings.spec = ParseDeviceSpec(*n, base);
    // A damping the scenario states is a measurement; the table's is not (0: inferred at Start).
    if (!n->Has("damping")) settings.spec->damping = 0.0;
    if (settings.spec->model.empty()) settings.spec->model = "Phantom";
    // The damping, when not measured, is inferred from the stiffness limit (phantom_device.cc).
    DeviceSpec check = *settings.spec;
    if (!(check.damping > 0.0) && check.max_stiffness > 0.0 && check.native_rate > 0.0) {
      check.damping = check.max_stiffness / check.native_rate / 2.0;
    }
    try {
      ValidateDeviceSpec(check);
    } catch (const UserError& e) {
      n->Fail("a complete device spec or a known model to start from", e.what());
    }
  }
  if (auto n = node.Find("name")) settings.device_name = n->AsString();
  if (auto n = node.Find("auto_calibrate")) settings.auto_calibrate = n->AsBool();
  if (auto n = node.Find("calibration_timeout")) {
    settings.calibration_timeout = n->AsQuantityIn(Dimension::kTime, 0.0, 3600.0);
  }
  if (auto n = node.Find("rate_tolerance")) {
    settings.rate_tolerance = n->AsQuantityIn(Dimension::kDimensionless, 0.0, 1.0, false);
  }
  if (auto frame = node.Find("frame")) {
    frame->ExpectOnlyKeys({"axes", "origin", "zero_button", "home"});
    if (auto n = frame->Find("axes")) settings.frame.axes = Axes(*n);
    if (auto n = frame->Find("origin")) settings.frame.origin = Point(*n);
    if (auto n = frame->Find("home")) settings.frame.home = Point(*n);
    if (auto n = frame->Find("zero_button")) {
      settings.frame.zero_button = 1u << (n->AsInteger(1, 32) - 1);
    }
  }
  if (auto faults = node.Find("faults")) {
    faults->ExpectOnlyKeys({"ramp_time", "max_faults", "fault_window", "derate_temperature"});
    if (auto n = faults->Find("ramp_time")) {
      settings.ramp_time = n->AsQuantityIn(Dimension::kTime, 0.0, 10.0);
    }
    if (auto n = faults->Find("max_faults")) settings.max_faults = static_cast<int>(n->AsInteger(1, 16));
    if (auto n = faults->Find("fault_window")) {
      settings.fault_window = n->AsQuantityIn(Dimension::kTime, 0.0, 3600.0, false);
    }
    if (auto n = faults->Find("derate_temperature")) {
      settings.derate_temperature = n->AsQuantityIn(Dimension::kDimensionless, 0.0, 1.0, false);
      if (!(settings.derate_temperature < 1.0)) n->Fail("a fraction below 1", n->Describe());
    }
  }
  Configure(settings);
}

}  // namespace fitfeel::phantom
