// ConfigNode-facing part of the device specs, kept apart so that code not parsing scenarios does
// not depend on the scenario parser.
#include <limits>

#include "framework/device/device_specs.h"

namespace fitfeel {

DeviceSpec ParseDeviceSpec(const ConfigNode& node, const DeviceSpec& base) {
  if (!node.is_map()) node.Fail("a map of device spec fields", node.Describe());
  node.ExpectOnlyKeys({"model", "max_force", "max_continuous_force", "max_stiffness", "damping",
                       "workspace", "native_rate", "force_mapping"});
  constexpr double kInf = std::numeric_limits<double>::infinity();
  DeviceSpec spec = base;
  if (std::optional<ConfigNode> model = node.Find("model")) {
    std::optional<DeviceSpec> known = FindDeviceSpec(model->AsString());
    if (!known) {
      std::string names;
      for (const DeviceSpec& s : KnownDeviceSpecs()) names += (names.empty() ? "" : ", ") + s.model;
      model->Fail("a known device model (" + names + ")", model->Describe());
    }
    spec = *known;
  }
  auto positive = [&](std::string_view key, Dimension dim, double* field) {
    if (std::optional<ConfigNode> child = node.Find(key)) {
      *field = child->AsQuantityIn(dim, 0.0, kInf, /*min_inclusive=*/false);
    }
  };
  positive("max_force", Dimension::kForce, &spec.max_force);
  positive("max_continuous_force", Dimension::kForce, &spec.max_continuous_force);
  // `unlimited`: a device that imposes its position (a robot, or a replay of one), to which the
  // runtime holds the part rigidly instead of through a god object's spring.
  if (std::optional<ConfigNode> child = node.Find("max_stiffness");
      child && child->is_scalar() && child->AsString() == "unlimited") {
    spec.max_stiffness = kInf;
  } else {
    positive("max_stiffness", Dimension::kStiffness, &spec.max_stiffness);
  }
  positive("damping", Dimension::kDamping, &spec.damping);
  positive("native_rate", Dimension::kFrequency, &spec.native_rate);
  if (std::optional<ConfigNode> mapping = node.Find("force_mapping")) {
    spec.force_mapping = mapping->AsOneOf({"linear", "perceptual"}) == "perceptual"
                             ? ForceMappingKind::kPerceptual
                             : ForceMappingKind::kLinear;
  }
  if (std::optional<ConfigNode> workspace = node.Find("workspace")) {
    if (!workspace->is_sequence() || workspace->Items().size() != 3) {
      workspace->Fail("a sequence of three lengths [x, y, z]", workspace->Describe());
    }
    std::vector<ConfigNode> items = workspace->Items();
    for (int i = 0; i < 3; ++i) {
      spec.workspace[i] = items[i].AsQuantityIn(Dimension::kLength, 0.0, kInf, false);
    }
  }
  if (spec.max_continuous_force > spec.max_force) {
    const ConfigNode at =
        node.Find("max_continuous_force").value_or(node.Find("max_force").value_or(node));
    at.Fail("max_continuous_force <= max_force (" +
                FormatQuantity(spec.max_force, Dimension::kForce) + ")",
            FormatQuantity(spec.max_continuous_force, Dimension::kForce));
  }
  return spec;
}

}  // namespace fitfeel
