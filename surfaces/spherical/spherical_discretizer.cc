#include "surfaces/spherical/spherical_discretizer.h"

#include <cmath>

#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {

GridShape SphericalDiscretizer::DoShape(const PartSpec& part, const Resolution& resolution) const {
  // Two-point sizes pair antipodal cells (row m-1-i, column j+n/2).
  return revolution::CheckedGridShape(part, resolution, GeometryOf(part).width(),
                                      {.row_pitch = 1e-3}, "a sphere", 2);
}

SurfaceGrid SphericalDiscretizer::DoDiscretize(const PartSpec& part,
                                               const Resolution& resolution) const {
  const SphericalGeometry& geometry = GeometryOf(part);
  const GridShape shape = DoShape(part, resolution);
  const double a = geometry.radius();
  const double h = geometry.width() / shape.rows;
  const double area = 2.0 * M_PI * a * h / shape.columns;
  return revolution::RevolvedGrid(shape, [&](int i) {
    const double y = -0.5 * geometry.width() + (i + 0.5) * h;
    const double rho = std::sqrt(a * a - y * y);  // distance from the axis
    // The normal points away from the centre: centre / a.
    return revolution::RevolvedRow{.y = y,
                                   .radius = rho,
                                   .area = area,
                                   .normal_radial = rho,
                                   .normal_axial = y,
                                   .normal_length = a};
  });
}

}  // namespace fitfeel::spherical
