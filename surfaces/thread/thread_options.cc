#include "surfaces/thread/thread_options.h"

#include <cmath>
#include <numeric>

#include "framework/core/quantity.h"

namespace fitfeel::thread {

double JointOptions::clamp_length() const {
  return std::accumulate(plates.begin(), plates.end(), 0.0);
}

namespace {

JointOptions ParseJoint(const ConfigNode& node) {
  if (!node.is_map()) node.Fail("a map {seat, plates, bearing_friction, ...}", node.Describe());
  node.ExpectOnlyKeys({"seat", "plates", "bearing_diameter", "hole_diameter", "bearing_friction",
                       "plate_outer_diameter", "plate_modulus", "shank", "property_class",
                       "stiffness"});
  JointOptions joint;
  joint.seat = node.QuantityIn("seat", Dimension::kLength, 0.0, 10.0);
  const ConfigNode plates = node.Child("plates");
  if (!plates.is_sequence() || plates.Items().empty()) {
    plates.Fail("a list of plate thicknesses (e.g. [10 mm, 10 mm])", plates.Describe());
  }
  for (const ConfigNode& plate : plates.Items()) {
    joint.plates.push_back(plate.AsQuantityIn(Dimension::kLength, 0.0, 10.0, false));
  }
  joint.bearing_friction = node.QuantityIn("bearing_friction", Dimension::kDimensionless, 0.0, 1.0);
  if (auto d = node.Find("bearing_diameter")) {
    joint.bearing_diameter = d->AsQuantityIn(Dimension::kLength, 0.0, 10.0, false);
  }
  if (auto d = node.Find("hole_diameter")) {
    joint.hole_diameter = d->AsQuantityIn(Dimension::kLength, 0.0, 10.0, false);
  }
  joint.plate_outer_diameter =
      node.Child("plate_outer_diameter").AsQuantityIn(Dimension::kLength, 0.0, 100.0, false);
  if (auto e = node.Find("plate_modulus")) {
    joint.plate_modulus = e->AsQuantityIn(Dimension::kPressure, 1e9, 1e12);
  }
  if (auto s = node.Find("shank")) joint.shank = s->AsQuantityIn(Dimension::kLength, 0.0, 10.0);
  if (joint.shank > joint.clamp_length()) {
    node.Child("shank").Fail("a shank no longer than the clamp length " +
                                 FormatQuantity(joint.clamp_length(), Dimension::kLength),
                             node.Child("shank").Describe());
  }
  if (auto c = node.Find("property_class")) {
    joint.property_class = c->AsOneOf({"4.6", "5.6", "8.8", "10.9", "12.9"});
  }
  if (auto k = node.Find("stiffness")) {
    joint.stiffness = k->AsQuantityIn(Dimension::kStiffness, 0.0, 1e13, false);
  }
  if (joint.bearing_diameter > 0.0 && joint.hole_diameter >= joint.bearing_diameter) {
    node.Child("hole_diameter")
        .Fail("a hole smaller than the bearing diameter " +
                  FormatQuantity(joint.bearing_diameter, Dimension::kLength),
              node.Child("hole_diameter").Describe());
  }
  return joint;
}

}  // namespace

std::shared_ptr<const ThreadOptions> ParseThreadOptions(const ConfigNode& options) {
  options.ExpectOnlyKeys({"distribution", "joint"});
  auto parsed = std::make_shared<ThreadOptions>();
  if (auto node = options.Find("distribution")) {
    parsed->distribution = node->AsOneOf({"uniform", "sopwith"}) == "uniform"
                               ? LoadDistribution::kUniform
                               : LoadDistribution::kSopwith;
  }
  if (auto node = options.Find("joint")) parsed->joint = ParseJoint(*node);
  return parsed;
}

ThreadOptions ThreadOptionsOf(const ModelSettings& settings) {
  return OptionsAs<ThreadOptions>(settings.options);
}

}  // namespace fitfeel::thread
