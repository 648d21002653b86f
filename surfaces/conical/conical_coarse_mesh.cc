#include "surfaces/conical/conical_coarse_mesh.h"

#include <algorithm>
#include <cmath>

#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {
namespace {

double Zone(const PartSpec& part) {
  return std::abs(part.size.upper_deviation - part.size.lower_deviation);
}

}  // namespace

CoarseMeshes MakeConicalCoarseMeshes(const PartSpec& inner, const PartSpec& outer) {
  const ConicalGeometry& pin = GeometryOf(inner);
  const ConicalGeometry& hole = GeometryOf(outer);
  const double radius = 0.5 * pin.large_diameter();
  const double radial_zone = 0.5 * (Zone(inner) + Zone(outer));
  const double finest = ChordalError(radius, kMaxCoarseFacets);
  const int facets =
      radial_zone > 0.0
          ? std::min(kMaxCoarseFacets, FacetsForChordalError(radius, std::max(radial_zone, finest)))
          : kMaxCoarseFacets;
  CoarseMeshes meshes;
  // The large end trails, at y = -L.
  meshes.inner = MakeClosedFrustum(0.5 * pin.large_diameter(), 0.5 * pin.small_diameter(),
                                   -pin.length(), 0.0, facets);
  meshes.outer = MakeTaperedTube(0.5 * hole.large_diameter(), 0.5 * hole.small_diameter(),
                                 0.5 * hole.outer_diameter(), 0.0, hole.length(), facets);
  return meshes;
}

}  // namespace fitfeel::conical
