#include "surfaces/cylindrical/cylindrical_geometry.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "framework/core/quantity.h"

namespace fitfeel::cylindrical {
namespace {
// Longest mating surface or largest diameter accepted: 10 m, well past any part a haptic
// device assembles, but it keeps typos like "20 m" for "20 mm" from making a billion cells.
constexpr double kMaxSize = 10.0;
}  // namespace

double CylindricalGeometry::DoNominalArea() const { return std::numbers::pi * diameter_ * length_; }

std::string CylindricalGeometry::DoDescribe() const {
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
  if (chamfer_.length > 0.0) {
    out << " chamfer " << mm(chamfer_.length) << " x "
        << std::round(chamfer_.angle * 180.0 / std::numbers::pi * 10.0) / 10.0 << " deg";
  }
  return out.str();
}

std::shared_ptr<const CylindricalGeometry> ParseCylindricalGeometry(const PartSpec& part,
                                                                    const ConfigNode& geometry) {
  const bool inner = part.role == Role::kInner;
  if (inner) {
    geometry.ExpectOnlyKeys({"length", "bore_diameter", "chamfer"});
  } else {
    geometry.ExpectOnlyKeys({"length", "outer_diameter", "chamfer"});
  }
  const double d = part.size.nominal;
  if (!(d > 0.0) || d > kMaxSize) {
    geometry.Fail("a part size (mating diameter) in (0, 10 m]",
                  FormatQuantity(d, Dimension::kLength));
  }
  const double length =
      geometry.Child("length").AsQuantityIn(Dimension::kLength, 0.0, kMaxSize, false);
  double outer_diameter = 0.0, bore_diameter = 0.0;
  if (inner) {
    if (auto node = geometry.Find("bore_diameter")) {
      bore_diameter = node->AsQuantityIn(Dimension::kLength, 0.0, kMaxSize);
      if (bore_diameter >= d) {
        node->Fail(
            "a bore diameter below the mating diameter " + FormatQuantity(d, Dimension::kLength),
            node->Describe());
      }
    }
  } else {
    const ConfigNode node = geometry.Child("outer_diameter");
    outer_diameter = node.AsQuantityIn(Dimension::kLength, 0.0, kMaxSize, false);
    if (outer_diameter <= d) {
      node.Fail(
          "a hub outer diameter above the mating diameter " + FormatQuantity(d, Dimension::kLength),
          node.Describe());
    }
  }
  auto parsed =
      std::make_shared<CylindricalGeometry>(part.role, d, length, outer_diameter, bore_diameter);
  if (auto node = geometry.Find("chamfer")) {
    const double wall = inner ? 0.5 * (d - bore_diameter) : 0.5 * (outer_diameter - d);
    parsed->set_chamfer(ParseChamfer(*node, length, wall));
  }
  return parsed;
}

void CheckCylindricalPair(const PartSpec& inner, const PartSpec& outer,
                          const ConfigNode& pair_node) {
  // One nominal size for both parts (ISO 286 fits are defined on it); 1 nm absorbs unit
  // conversion rounding only.
  if (std::abs(inner.size.nominal - outer.size.nominal) > 1e-9) {
    pair_node.Fail("the same nominal diameter for both parts of a cylindrical fit",
                   "'" + inner.name + "' " +
                       FormatQuantity(inner.size.nominal, Dimension::kLength) + " and '" +
                       outer.name + "' " + FormatQuantity(outer.size.nominal, Dimension::kLength));
  }
}

}  // namespace fitfeel::cylindrical
