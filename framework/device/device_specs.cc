#include "framework/device/device_specs.h"

#include <cctype>
#include <cmath>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

// Peak force, max stable stiffness and damping: docs/oracles.md ("Haptic
// stability and devices"), which the stability tests use as their oracle.
// Continuous force and workspace: the SensAble / Geomagic / 3D Systems data sheets as published
// for each model (PHANTOM Desktop: 1.75 N continuous for 24 h, 160 W x 120 H x 120 D mm; PHANTOM
// Omni and Touch: 0.88 N continuous, 160 W x 120 H x 70 D mm). Two approximations: the real
// workspace is not a box (the box is the data sheet's nominal W x H x D), and the continuous force
// is a thermal rating the safety chain enforces through a first-order thermal model whose time
// constant is a setting, not a data-sheet value. Axes follow OpenHaptics: x right, y up, z towards
// the user.
DeviceSpec MakeSpec(std::string model, double max_force, double max_continuous_force,
                    double max_stiffness, double damping, Eigen::Vector3d workspace) {
  DeviceSpec spec;
  spec.model = std::move(model);
  spec.max_force = max_force;
  spec.max_continuous_force = max_continuous_force;
  spec.max_stiffness = max_stiffness;
  spec.damping = damping;
  spec.workspace = workspace;
  spec.native_rate = 1000.0;  // OpenHaptics servo loop rate for all three
  return spec;
}

// The PHANTOM Premium models: peak force, continuous force, stiffness and workspace from
// SensAble's data sheets as recalled, not checked against a copy here. The sheets give no
// damping; the one a sampled wall of the sheet's stiffness K needs to be passive at the 1 kHz servo
// rate, b = K T / 2 (Colgate & Schenkel 1997), stands in for it. Being inferred rather than
// measured, the passivity observer does not count it as dissipation (credit_damping = false).
DeviceSpec MakePremiumSpec(std::string model, double max_force, double max_continuous_force,
                           double max_stiffness, Eigen::Vector3d workspace) {
  constexpr double kServoPeriod = 1e-3;  // s
  DeviceSpec spec = MakeSpec(std::move(model), max_force, max_continuous_force, max_stiffness,
                             max_stiffness * kServoPeriod / 2.0, workspace);
  spec.credit_damping = false;
  return spec;
}

std::string Normalize(std::string_view name) {
  std::string out;
  for (char c : name) {
    if (c == ' ' || c == '-' || c == '_' || c == '\t') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

struct Alias {
  const char* alias;
  const char* model;
};

constexpr Alias kAliases[] = {
    {"phantomdesktop", "PHANTOM Desktop"},
    {"desktop", "PHANTOM Desktop"},
    {"geomagicdesktop", "PHANTOM Desktop"},
    {"phantomomni", "PHANTOM Omni"},
    {"omni", "PHANTOM Omni"},
    {"touch", "Touch"},
    {"geomagictouch", "Touch"},
    {"3dsystemstouch", "Touch"},
    {"premium1.0", "PHANTOM Premium 1.0"},
    {"premium1.5", "PHANTOM Premium 1.5"},
    {"premium1.5hf", "PHANTOM Premium 1.5 High Force"},
    {"phantompremium1.5hf", "PHANTOM Premium 1.5 High Force"},
    {"premium1.5highforce", "PHANTOM Premium 1.5 High Force"},
    {"premium3.0", "PHANTOM Premium 3.0"},
};

bool PositiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

std::string KnownDeviceModels() {
  std::string out;
  for (const DeviceSpec& spec : KnownDeviceSpecs()) {
    if (!out.empty()) out += ", ";
    out += "'" + spec.model + "'";
  }
  return out;
}

const std::vector<DeviceSpec>& KnownDeviceSpecs() {
  static const std::vector<DeviceSpec> specs = {
      MakeSpec("PHANTOM Desktop", 7.9, 1.75, 1000.0, 5.0, {0.160, 0.120, 0.120}),
      MakeSpec("PHANTOM Omni", 3.3, 0.88, 700.0, 5.0, {0.160, 0.120, 0.070}),
      MakeSpec("Touch", 3.3, 0.88, 400.0, 4.0, {0.160, 0.120, 0.070}),
      MakePremiumSpec("PHANTOM Premium 1.0", 8.5, 1.4, 3500.0, {0.254, 0.178, 0.127}),
      MakePremiumSpec("PHANTOM Premium 1.5", 8.5, 1.4, 3500.0, {0.381, 0.267, 0.191}),
      MakePremiumSpec("PHANTOM Premium 1.5 High Force", 37.5, 6.2, 3500.0, {0.381, 0.267, 0.191}),
      MakePremiumSpec("PHANTOM Premium 3.0", 22.0, 3.0, 1000.0, {0.838, 0.584, 0.406}),
  };
  return specs;
}

std::optional<DeviceSpec> FindDeviceSpec(std::string_view model) {
  const std::string key = Normalize(model);
  if (key.empty()) return std::nullopt;
  std::string target = key;
  for (const Alias& alias : kAliases) {
    if (key == alias.alias) target = Normalize(alias.model);
  }
  for (const DeviceSpec& spec : KnownDeviceSpecs()) {
    if (Normalize(spec.model) == target) return spec;
  }
  return std::nullopt;
}

DeviceSpec LookupDeviceSpec(std::string_view model) {
  std::optional<DeviceSpec> spec = FindDeviceSpec(model);
  if (!spec) {
    throw UserError("unknown haptic device model '" + std::string(model) +
                    "'; known models: " + KnownDeviceModels() +
                    " (or give max_force, max_continuous_force, max_stiffness, damping, workspace "
                    "in the device's spec section)");
  }
  return *spec;
}

void ValidateDeviceSpec(const DeviceSpec& spec) {
  const std::string who = "device spec '" + spec.model + "': ";
  if (!PositiveFinite(spec.max_force)) throw UserError(who + "max_force must be positive");
  if (!PositiveFinite(spec.max_continuous_force)) {
    throw UserError(who + "max_continuous_force must be positive");
  }
  if (spec.max_continuous_force > spec.max_force) {
    throw UserError(who + "max_continuous_force exceeds max_force");
  }
  // Infinite: the device imposes its position (see ParseDeviceSpec's `unlimited`).
  if (!(spec.max_stiffness > 0.0)) throw UserError(who + "max_stiffness must be positive");
  if (!PositiveFinite(spec.damping)) throw UserError(who + "damping must be positive");
  if (!(spec.workspace.allFinite() && (spec.workspace.array() > 0.0).all())) {
    throw UserError(who + "workspace extents must be positive");
  }
  if (!PositiveFinite(spec.native_rate)) throw UserError(who + "native_rate must be positive");
}

}  // namespace fitfeel
