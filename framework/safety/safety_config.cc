// ConfigNode-facing part of the safety settings, kept apart from the per-tick code.
#include <limits>

#include "framework/safety/safety_settings.h"

namespace fitfeel {

SafetySettings ParseSafetySettings(const ConfigNode& node) {
  SafetySettings settings;
  if (!node.is_map()) {
    if (node.is_null()) return settings;
    node.Fail("a map of safety settings", node.Describe());
  }
  node.ExpectOnlyKeys({"force_scale", "physical_full_scale", "continuous_window", "coupling",
                       "coupling_stiffness", "coupling_damping", "proxy_mass",
                       "credit_device_damping", "passivity_controller", "passivity_max_damping",
                       "torque_lever", "force_mapping", "mapping_knee", "mapping_top"});
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (node.Has("force_scale") && node.Has("physical_full_scale")) {
    node.Child("physical_full_scale")
        .Fail("either force_scale or physical_full_scale, not both", "both");
  }
  if (auto n = node.Find("force_mapping")) {
    const bool perceptual = n->AsOneOf({"linear", "perceptual"}) == "perceptual";
    settings.force_mapping = perceptual ? ForceMappingKind::kPerceptual : ForceMappingKind::kLinear;
    // One factor for every force and a map that compresses them cannot both hold.
    for (const char* key : {"force_scale", "physical_full_scale"}) {
      if (perceptual && node.Has(key)) {
        node.Child(key).Fail(std::string("no ") + key +
                                 " with force_mapping: perceptual (the map "
                                 "sets the device's force itself)",
                             std::string(key) + " and force_mapping: perceptual");
      }
    }
  } else if (node.Has("force_scale") || node.Has("physical_full_scale")) {
    settings.force_mapping = ForceMappingKind::kLinear;
  }
  // Up to a meganewton: beyond any bench press.
  if (auto n = node.Find("mapping_knee")) {
    settings.mapping_knee = n->AsQuantityIn(Dimension::kForce, 0.0, 1e6, false);
  }
  if (auto n = node.Find("mapping_top")) {
    settings.mapping_top = n->AsQuantityIn(Dimension::kForce, 0.0, 1e6, false);
  }
  if (!(settings.mapping_knee < settings.mapping_top)) {
    if (auto knee = node.Find("mapping_knee")) {
      knee->Fail("a mapping_knee below mapping_top (" +
                     FormatQuantity(settings.mapping_top, Dimension::kForce) + ")",
                 knee->Describe());
    }
    const ConfigNode top = node.Child("mapping_top");
    top.Fail("a mapping_top above mapping_knee (" +
                 FormatQuantity(settings.mapping_knee, Dimension::kForce) + ")",
             top.Describe());
  }
  if (auto n = node.Find("torque_lever")) {
    // From a finger on a nut's flats (a few mm) to a long wrench (1 m).
    settings.torque_lever = n->AsQuantityIn(Dimension::kLength, 1e-3, 1.0);
  }
  if (auto n = node.Find("force_scale")) {
    settings.force_scale = n->AsQuantityIn(Dimension::kDimensionless, 0.0, kInf, false);
  }
  if (auto n = node.Find("physical_full_scale")) {
    settings.physical_full_scale = n->AsQuantityIn(Dimension::kForce, 0.0, kInf, false);
  }
  if (auto n = node.Find("continuous_window")) {
    settings.continuous_window = n->AsQuantityIn(Dimension::kTime, 0.0, kInf, false);
  }
  if (auto n = node.Find("coupling")) {
    settings.coupling = n->AsOneOf({"spring_damper", "direct"}) == "direct"
                            ? CouplingMode::kDirect
                            : CouplingMode::kSpringDamper;
  }
  if (auto n = node.Find("coupling_stiffness")) {
    settings.coupling_stiffness = n->AsQuantityIn(Dimension::kStiffness, 0.0, kInf, false);
  }
  if (auto n = node.Find("coupling_damping")) {
    settings.coupling_damping = n->AsQuantityIn(Dimension::kDamping, 0.0, kInf);
  }
  if (auto n = node.Find("proxy_mass")) {
    settings.proxy_mass = n->AsQuantityIn(Dimension::kMass, 0.0, kInf);
  }
  if (auto n = node.Find("credit_device_damping")) settings.credit_device_damping = n->AsBool();
  if (auto n = node.Find("passivity_controller")) settings.passivity_controller = n->AsBool();
  if (auto n = node.Find("passivity_max_damping")) {
    settings.passivity_max_damping = n->AsQuantityIn(Dimension::kDamping, 0.0, kInf);
  }
  return settings;
}

SafetySection ParseSafetySection(const ConfigNode& node) {
  SafetySection section;
  section.settings = ParseSafetySettings(node);
  section.names_coupling = node.is_map() && node.Has("coupling");
  return section;
}

}  // namespace fitfeel
