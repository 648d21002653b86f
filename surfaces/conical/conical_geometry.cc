#include "surfaces/conical/conical_geometry.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::conical {
namespace {

// Steeper than 1:2 (half angle 14 deg) is no longer a self-holding taper fit but a cone seat of
// another kind (tool tapers are 7:24 at most), and flatter than 1:1000 cannot be reamed.
constexpr double kMinTaper = 1e-3;
constexpr double kMaxTaper = 0.5;
// A mating length of 10 m describes no pin or hub.
constexpr double kMaxLength = 10.0;

double ParseTaper(const ConfigNode& node) {
  const char* const expected = "a taper ratio as '1:N' (e.g. 1:50) or a number C = 2 tan(alpha)";
  const std::string text = node.AsString();
  const std::size_t colon = text.find(':');
  double ratio = 0.0;
  if (colon == std::string::npos) {
    ratio = node.AsQuantity(Dimension::kDimensionless);
  } else {
    double left = 0.0, right = 0.0;
    try {
      std::size_t used_left = 0, used_right = 0;
      const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
      left = std::stod(a, &used_left);
      right = std::stod(b, &used_right);
      if (used_left != a.size() || used_right != b.size()) node.Fail(expected, node.Describe());
    } catch (const std::logic_error&) {
      node.Fail(expected, node.Describe());
    }
    if (!(left > 0.0) || !(right > 0.0)) node.Fail(expected, node.Describe());
    ratio = left / right;
  }
  if (!(ratio >= kMinTaper && ratio <= kMaxTaper)) {
    node.Fail("a taper ratio between 1:1000 and 1:2", node.Describe());
  }
  return ratio;
}

}  // namespace

ConicalGeometry::ConicalGeometry(Role role, double small_diameter, double length, double taper,
                                 double outer_diameter)
    : role_(role),
      small_diameter_(small_diameter),
      length_(length),
      taper_(taper),
      half_angle_(std::atan(0.5 * taper)),
      outer_diameter_(outer_diameter) {}

double ConicalGeometry::DiameterAt(double axial) const {
  return role_ == Role::kInner ? small_diameter_ + taper_ * axial
                               : small_diameter_ + taper_ * (length_ - axial);
}

double ConicalGeometry::DoNominalArea() const {
  // Lateral area of a frustum: pi * mean diameter * slant length.
  return M_PI * mean_diameter() * length_ / std::cos(half_angle_);
}

std::string ConicalGeometry::DoDescribe() const {
  char ratio[32];
  std::snprintf(ratio, sizeof ratio, "1:%.4g", 1.0 / taper_);
  std::string text = std::string(role_ == Role::kInner ? "taper pin" : "taper hole") +
                     " d=" + FormatQuantity(small_diameter_, Dimension::kLength) +
                     " l=" + FormatQuantity(length_, Dimension::kLength) + " taper " + ratio;
  if (role_ == Role::kOuter) {
    text += " hub D=" + FormatQuantity(outer_diameter_, Dimension::kLength);
  }
  return text + DescribeChamfer(chamfer_);
}

std::shared_ptr<const ConicalGeometry> ParseConicalGeometry(const PartSpec& part,
                                                            const ConfigNode& node) {
  if (!node.is_map())
    node.Fail("a map of the cone's geometry (length, taper, ...)", node.Describe());
  const bool outer = part.role == Role::kOuter;
  if (outer) {
    node.ExpectOnlyKeys({"length", "taper", "outer_diameter", "chamfer"});
  } else {
    node.ExpectOnlyKeys({"length", "taper", "chamfer"});
  }
  const double length = node.Child("length").AsQuantityIn(Dimension::kLength, 0.0, kMaxLength,
                                                          /*min_inclusive=*/false);
  const double taper = ParseTaper(node.Child("taper"));
  double outer_diameter = 0.0;
  const double d = part.size.nominal;
  if (outer) {
    const ConfigNode d2 = node.Child("outer_diameter");
    outer_diameter = d2.AsQuantity(Dimension::kLength);
    const double large = d + taper * length;
    // The Lame solution needs a hub wall all along the bore, at its large end too.
    if (!(outer_diameter > large)) {
      d2.Fail("a hub outer diameter above the bore's large-end diameter (" +
                  FormatQuantity(large, Dimension::kLength) + ")",
              d2.Describe());
    }
  }
  auto parsed = std::make_shared<ConicalGeometry>(part.role, d, length, taper, outer_diameter);
  if (auto chamfer = node.Find("chamfer")) {
    // The pin's chamfer cuts its small end (solid), the hole's its hub at the large end.
    const double wall = outer ? 0.5 * (outer_diameter - parsed->large_diameter()) : 0.5 * d;
    parsed->set_chamfer(ParseChamfer(*chamfer, length, wall));
  }
  return parsed;
}

const ConicalGeometry& GeometryOf(const PartSpec& part) {
  const auto* geometry = dynamic_cast<const ConicalGeometry*>(part.geometry.get());
  if (geometry == nullptr) {
    throw UserError("part '" + part.name + "' has no conical geometry");
  }
  return *geometry;
}

}  // namespace fitfeel::conical
