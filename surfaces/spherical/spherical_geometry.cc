#include "surfaces/spherical/spherical_geometry.h"

#include <cmath>
#include <string>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::spherical {

double SphericalGeometry::mean_axis_distance() const {
  const double a = radius(), h = 0.5 * width_;
  // Antiderivative of sqrt(a^2 - y^2): (y sqrt(a^2 - y^2) + a^2 asin(y / a)) / 2.
  return (h * std::sqrt(a * a - h * h) + a * a * std::asin(h / a)) / width_;
}

double SphericalGeometry::DoNominalArea() const { return M_PI * diameter_ * width_; }

std::string SphericalGeometry::DoDescribe() const {
  std::string text = std::string(role_ == Role::kInner ? "ball" : "socket") +
                     " dk=" + FormatQuantity(diameter_, Dimension::kLength) +
                     " band B=" + FormatQuantity(width_, Dimension::kLength);
  if (role_ == Role::kOuter) {
    text += " ring D=" + FormatQuantity(outer_diameter_, Dimension::kLength);
  }
  if (bore_diameter_ > 0.0) {
    text += " bore d=" + FormatQuantity(bore_diameter_, Dimension::kLength);
  }
  return text;
}

std::shared_ptr<const SphericalGeometry> ParseSphericalGeometry(const PartSpec& part,
                                                                const ConfigNode& node) {
  if (!node.is_map()) node.Fail("a map of the sphere's geometry (width, ...)", node.Describe());
  const bool outer = part.role == Role::kOuter;
  if (outer) {
    node.ExpectOnlyKeys({"width", "outer_diameter"});
  } else {
    node.ExpectOnlyKeys({"width", "bore_diameter"});
  }
  const double d = part.size.nominal;
  // A band as wide as the sphere would be the whole sphere, which no ring is (it must be
  // assembled and carry a bore); 0.9 d keeps every cell off the poles.
  const double width = node.Child("width").AsQuantityIn(Dimension::kLength, 0.0, 0.9 * d,
                                                        /*min_inclusive=*/false);
  double outer_diameter = 0.0;
  if (outer) {
    const ConfigNode ring = node.Child("outer_diameter");
    outer_diameter = ring.AsQuantity(Dimension::kLength);
    // The thick-shell solution needs a wall around the socket.
    if (!(outer_diameter > d)) {
      ring.Fail("an outer ring diameter above the sphere diameter (" +
                    FormatQuantity(d, Dimension::kLength) + ")",
                ring.Describe());
    }
  }
  double bore_diameter = 0.0;
  if (auto bore = node.Find("bore_diameter")) {
    bore_diameter = bore->AsQuantityIn(Dimension::kLength, 0.0, d);
    // The inner ring's wall is thinnest at its band's edges, where the sphere's radius from the
    // axis is sqrt(a^2 - (B/2)^2): the bore must stay inside it.
    const double a = 0.5 * d, h = 0.5 * width;
    const double edge = 2.0 * std::sqrt(a * a - h * h);
    if (!(bore_diameter < edge)) {
      bore->Fail("a bore diameter below the band edge's diameter " +
                     FormatQuantity(edge, Dimension::kLength) + " (dk and width leave no wall)",
                 bore->Describe());
    }
  }
  return std::make_shared<SphericalGeometry>(part.role, d, width, outer_diameter, bore_diameter);
}

const SphericalGeometry& GeometryOf(const PartSpec& part) {
  const auto* geometry = dynamic_cast<const SphericalGeometry*>(part.geometry.get());
  if (geometry == nullptr) throw UserError("part '" + part.name + "' has no spherical geometry");
  return *geometry;
}

}  // namespace fitfeel::spherical
