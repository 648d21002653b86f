// Test double for the out-of-line members of CylindricalGeometry (declared in
// cylindrical_geometry.h, implemented with the generation code on another branch), so that the
// contact tests and benchmarks build and run without that code.
#include <numbers>
#include <string>

#include "surfaces/cylindrical/cylindrical_geometry.h"

namespace fitfeel::cylindrical {

double CylindricalGeometry::nominal_area() const { return std::numbers::pi * diameter_ * length_; }

std::string CylindricalGeometry::Describe() const { return "cylinder (test double)"; }

}  // namespace fitfeel::cylindrical
