#include "surfaces/conical/conical_discretizer.h"

#include <cmath>

#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {

GridShape ConicalDiscretizer::DoShape(const PartSpec& part, const Resolution& resolution) const {
  // An axis needs three sections to be anything but straight.
  return revolution::CheckedGridShape(part, resolution, GeometryOf(part).length(),
                                      {.row_pitch = 2e-3}, "a cone", 3);
}

SurfaceGrid ConicalDiscretizer::DoDiscretize(const PartSpec& part,
                                             const Resolution& resolution) const {
  const ConicalGeometry& geometry = GeometryOf(part);
  const GridShape shape = DoShape(part, resolution);
  const double h = geometry.length() / shape.rows;
  const double alpha = geometry.half_angle();
  // Radius grows towards +t on the pin and shrinks towards +y in the hole, so the normal away
  // from the axis leans back along the axis on the pin and forward in the hole.
  const double axial_normal = (part.role == Role::kInner ? -1.0 : 1.0) * std::sin(alpha);
  return revolution::RevolvedGrid(shape, [&](int i) {
    const double y = (i + 0.5) * h;
    const double radius = 0.5 * geometry.DiameterAt(y);
    const double area = 2.0 * M_PI * radius / shape.columns * h / std::cos(alpha);
    return revolution::RevolvedRow{.y = y,
                                   .radius = radius,
                                   .area = area,
                                   .normal_radial = std::cos(alpha),
                                   .normal_axial = axial_normal};
  });
}

}  // namespace fitfeel::conical
