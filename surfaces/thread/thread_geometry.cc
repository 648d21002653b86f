#include "surfaces/thread/thread_geometry.h"

#include <cmath>
#include <numbers>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::thread {

HelicoidGeometry::HelicoidGeometry(Role role, double diameter, double pitch, double flank_angle,
                                   double length)
    : role_(role), diameter_(diameter), pitch_(pitch), flank_angle_(flank_angle), length_(length) {}

double HelicoidGeometry::triangle_height() const { return pitch_ / (2.0 * std::tan(half_angle())); }
double HelicoidGeometry::inner_radius() const {
  return 0.5 * diameter_ - 5.0 / 8.0 * triangle_height();
}
double HelicoidGeometry::pitch_radius() const {
  return 0.5 * diameter_ - 3.0 / 8.0 * triangle_height();
}

double HelicoidGeometry::AreaPrimitive(double r) const {
  const double k = std::tan(half_angle());
  const double a = std::sqrt(1.0 + k * k);
  const double c = pitch_ / (2.0 * std::numbers::pi);
  return 0.5 * r * std::sqrt(a * a * r * r + c * c) + c * c / (2.0 * a) * std::asinh(a * r / c);
}

double HelicoidGeometry::flank_area() const {
  return 2.0 * std::numbers::pi * turns() *
         (AreaPrimitive(outer_radius()) - AreaPrimitive(inner_radius()));
}

std::string HelicoidGeometry::DoDescribe() const {
  return "thread d=" + FormatQuantity(diameter_, Dimension::kLength) +
         " P=" + FormatQuantity(pitch_, Dimension::kLength) +
         " flank angle=" + FormatQuantity(flank_angle_, Dimension::kAngle) +
         " L=" + FormatQuantity(length_, Dimension::kLength);
}

std::shared_ptr<const HelicoidGeometry> ParseHelicoidGeometry(const PartSpec& part,
                                                              const ConfigNode& node) {
  if (!node.is_map()) {
    node.Fail("a map {length, pitch, flank_angle}", node.Describe());
  }
  node.ExpectOnlyKeys({"nominal_diameter", "pitch", "flank_angle", "length"});
  const double d = part.size.nominal;
  if (std::optional<ConfigNode> nominal = node.Find("nominal_diameter")) {
    const double given = nominal->AsQuantity(Dimension::kLength);
    if (std::abs(given - d) > 1e-12) {
      nominal->Fail("the part's nominal size " + FormatQuantity(d, Dimension::kLength),
                    nominal->Describe());
    }
  }
  // An ISO thread designation (size: M10x1.5 6g) gives the pitch; a pitch beside it must agree.
  // ISO 261 coarse pitches stay below d/4 (M1 x 0.25); a pitch above d/3 leaves no core.
  double pitch = part.size.pitch;
  if (std::optional<ConfigNode> given = node.Find("pitch")) {
    pitch = given->AsQuantityIn(Dimension::kLength, 1e-6, d / 3.0);
    if (part.size.pitch > 0.0 && std::abs(pitch - part.size.pitch) > 1e-12) {
      given->Fail("the pitch of the part's size " + part.size.iso_code + " (" +
                      FormatQuantity(part.size.pitch, Dimension::kLength) + ")",
                  given->Describe());
    }
  } else if (!(pitch > 0.0)) {
    node.Fail("a pitch (or a size given as an ISO thread designation, e.g. 'M10x1.5 6g')",
              "no `pitch` and a size '" + FormatQuantity(d, Dimension::kLength) + "'");
  }
  // Symmetric V and trapezoidal threads: 29 deg (ACME) and 30 deg (ISO 2904) up to 60 deg
  // (ISO 68-1, the default) and beyond; below 20 deg or above 120 deg no standard thread exists.
  constexpr double kDeg = std::numbers::pi / 180.0;
  double angle = 60.0 * kDeg;
  if (std::optional<ConfigNode> given = node.Find("flank_angle")) {
    angle = given->AsQuantityIn(Dimension::kAngle, 20.0 * kDeg, 120.0 * kDeg);
  }
  if (part.size.pitch > 0.0 && std::abs(angle - 60.0 * kDeg) > 1e-12) {
    node.Child("flank_angle")
        .Fail("60 deg, the ISO 68-1 flank angle of the part's size " + part.size.iso_code,
              node.Child("flank_angle").Describe());
  }
  // At least one turn; beyond 100 diameters no thread is engaged at once.
  const double length = node.QuantityIn("length", Dimension::kLength, pitch, 100.0 * d);
  // The deviation limits are the part's `form:` (ThreadSurface::declared_characteristics). A
  // pitch deviation above a tenth of the pitch is a different thread, not a deviation of this one.
  const double pitch_error = part.form.Declared("pitch_error");
  if (pitch_error > 0.1 * pitch) {
    const ConfigNode at = node.Has("pitch") ? node.Child("pitch") : node;
    at.Fail("a pitch at least 10 times the form's pitch_error (" +
                FormatQuantity(pitch_error, Dimension::kLength) + ")",
            FormatQuantity(pitch, Dimension::kLength));
  }
  return std::make_shared<HelicoidGeometry>(part.role, d, pitch, angle, length);
}

const HelicoidGeometry& HelicoidGeometryOf(const PartSpec& part) {
  const auto* g = dynamic_cast<const HelicoidGeometry*>(part.geometry.get());
  if (g == nullptr) throw UserError("part '" + part.name + "' has no helicoid geometry");
  return *g;
}

}  // namespace fitfeel::thread
