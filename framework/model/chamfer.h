#pragma once

#include <cmath>
#include <string>

#include "framework/core/config_node.h"
#include "framework/core/export.h"

namespace fitfeel {

// A lead-in chamfer at a part's mating end (a shaft's or pin's leading end, a bore's entrance):
// `length` along the axis, the chamfer surface at `angle` to the axis, so it is
// length * tan(angle) wide radially (docs/lead-in.md). Zero length: a sharp edge.
struct Chamfer {
  double length = 0.0;  // m
  double angle = 0.0;   // rad, in (0, 90 deg)
  double width() const { return length > 0.0 ? length * std::tan(angle) : 0.0; }
};

// Parses a part's `geometry.chamfer` key: a length (45 degrees, ISO 13715's plain "C" edge) or
// {length, angle} with the angle in [1, 80] degrees (flatter is no lead-in, steeper no chamfer).
// The chamfer must be shorter than the part and narrower than the wall it cuts; otherwise the
// key fails with its location, what was expected and what was found.
FITFEEL_API Chamfer ParseChamfer(const ConfigNode& node, double part_length, double wall);

// " chamfer <length> x <width>" for a geometry's description; empty for a sharp edge.
FITFEEL_API std::string DescribeChamfer(const Chamfer& chamfer);

}  // namespace fitfeel
