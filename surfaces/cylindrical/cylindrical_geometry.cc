#include "surfaces/cylindrical/cylindrical_geometry.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace fitfeel::cylindrical {

double CylindricalGeometry::nominal_area() const { return std::numbers::pi * diameter_ * length_; }

std::string CylindricalGeometry::Describe() const {
  std::ostringstream out;
  // Millimetres with up to 4 decimals: 20 mm, 19.9875 mm.
  auto mm = [](double m) {
    std::ostringstream s;
    s << std::round(m * 1e7) / 1e4 << " mm";
    return s.str();
  };
  out << (role_ == Role::kInner ? "shaft" : "bore") << " d=" << mm(diameter_)
      << " l=" << mm(length_);
  if (role_ == Role::kOuter) out << " hub outer d=" << mm(outer_diameter_);
  if (role_ == Role::kInner && bore_diameter_ > 0.0)
    out << " hollow, bore d=" << mm(bore_diameter_);
  return out.str();
}

}  // namespace fitfeel::cylindrical
