#pragma once

#include <memory>
#include <string>

#include "framework/model/gps_spec.h"
#include "surfaces/planar/planar_geometry.h"

namespace fitfeel::planar::testing {

// A part of the planar surface without a scenario file: C45 steel, explicit size deviations.
inline PartSpec MakePart(std::string name, Role role, double width, double lower, double upper,
                         double length, double height, int faces = 2) {
  PartSpec p;
  p.name = std::move(name);
  p.role = role;
  p.size.nominal = width;
  p.size.lower_deviation = lower;
  p.size.upper_deviation = upper;
  p.material = {"C45", 210e9, 0.3};
  p.geometry = std::make_shared<PlanarGeometry>(role, width, length, height, faces);
  return p;
}

}  // namespace fitfeel::planar::testing
