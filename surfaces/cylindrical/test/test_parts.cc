#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical::testing {

PartSpec Part(std::string name, Role role, double diameter, double length, double lower,
              double upper) {
  PartSpec p;
  p.name = std::move(name);
  p.role = role;
  p.size.nominal = diameter;
  p.size.lower_deviation = lower;
  p.size.upper_deviation = upper;
  p.geometry = std::make_shared<CylindricalGeometry>(
      role, diameter, length, role == Role::kOuter ? 1.5 * diameter : 0.0, 0.0);
  return p;
}

PartSpec PaperShaft() {
  PartSpec p = Part("shaft", Role::kInner, 0.020, 0.060, -8e-6, 8e-6);
  p.form.tolerance[FormCharacteristic::kAxisStraightness] = 10e-6;
  p.form.tolerance[FormCharacteristic::kRoundness] = 10e-6;
  p.texture = {3.2e-6, 0.4e-6, 1.6e-6};
  return p;
}

PartSpec PaperHole() {
  PartSpec p = Part("bushing", Role::kOuter, 0.020, 0.020, 0.0, 25e-6);
  p.form.tolerance[FormCharacteristic::kAxisStraightness] = 10e-6;
  p.form.tolerance[FormCharacteristic::kRoundness] = 10e-6;
  p.texture = {3.2e-6, 0.4e-6, 1.6e-6};
  return p;
}

}  // namespace fitfeel::cylindrical::testing
