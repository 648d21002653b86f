#pragma once

// The thick-shell oracle's parts (docs/oracles.md): a steel ball of radius a = 10 mm in a
// shell of outer radius b = 15 mm; bands of 14 mm (ball) and 10 mm (socket).
#include <memory>

#include "framework/model/gps_spec.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical::test {

inline Material Steel() { return Material{"steel", 210e9, 0.3}; }

inline PartSpec Ball(double width = 14e-3) {
  PartSpec p;
  p.name = "ball";
  p.role = Role::kInner;
  p.size.nominal = 20e-3;
  p.material = Steel();
  p.geometry = std::make_shared<SphericalGeometry>(Role::kInner, 20e-3, width, 0.0);
  return p;
}

inline PartSpec Socket(double width = 10e-3, double outer_diameter = 30e-3) {
  PartSpec p;
  p.name = "socket";
  p.role = Role::kOuter;
  p.size.nominal = 20e-3;
  p.material = Steel();
  p.geometry = std::make_shared<SphericalGeometry>(Role::kOuter, 20e-3, width, outer_diameter);
  return p;
}

}  // namespace fitfeel::spherical::test
