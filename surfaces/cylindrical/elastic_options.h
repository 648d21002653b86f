#pragma once

#include <limits>

#include "framework/core/config_node.h"
#include "framework/core/quantity.h"

namespace fitfeel::cylindrical {

// The elastic model's keys under `model.options` (law `elastic`):
//   tilt: free | fixed | <holder's angular stiffness, N*m/rad>   (default free)
//   section: plane_stress | plane_strain                          (default plane_stress)
struct ElasticOptions {
  bool tilt = true;             // the moving part may tilt (4 DOF) or not (2 DOF)
  double tilt_stiffness = 0.0;  // what holds its tilt, N*m/rad (0 = nothing)
  bool plane_strain = false;
};

inline ElasticOptions ParseElasticOptions(const ConfigNode& options) {
  ElasticOptions o;
  if (auto node = options.Find("tilt")) {
    const std::string text = node->AsString();
    if (text == "fixed") {
      o.tilt = false;
    } else if (text != "free") {
      o.tilt_stiffness = node->AsQuantityIn(Dimension::kAngularStiffness, 0.0,
                                            std::numeric_limits<double>::max());
    }
  }
  if (auto node = options.Find("section")) {
    o.plane_strain = node->AsOneOf({"plane_stress", "plane_strain"}) == "plane_strain";
  }
  return o;
}

}  // namespace fitfeel::cylindrical
