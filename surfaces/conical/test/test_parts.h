#pragma once

// Parts of the DIN 7190 oracle: an ISO 2339 pin 8 x 40 (1:50) in a 20 mm hub of outer diameter
// 24 mm, steel on steel, with every tolerance zero unless a test sets one.
#include <memory>

#include "framework/model/gps_spec.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical::test {

// The hub's length: the bore's mean diameter is 8.2 mm over it.
inline constexpr double kHoleLength = 20e-3;

inline Material Steel() { return Material{"steel", 210e9, 0.3}; }

inline PartSpec Pin(double length = 40e-3) {
  PartSpec p;
  p.name = "pin";
  p.role = Role::kInner;
  p.size.nominal = 8e-3;
  p.material = Steel();
  p.geometry = std::make_shared<ConicalGeometry>(Role::kInner, 8e-3, length, 1.0 / 50.0, 0.0);
  return p;
}

inline PartSpec Hole(double length = kHoleLength, double outer_diameter = 24e-3) {
  PartSpec p;
  p.name = "hole";
  p.role = Role::kOuter;
  p.size.nominal = 8e-3;
  p.material = Steel();
  p.geometry =
      std::make_shared<ConicalGeometry>(Role::kOuter, 8e-3, length, 1.0 / 50.0, outer_diameter);
  return p;
}

}  // namespace fitfeel::conical::test
