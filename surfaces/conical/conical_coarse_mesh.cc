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
  // The large end trails, at y = -L; a chamfer narrows the small end over its last c_p.
  const Chamfer& end = pin.chamfer();
  const double tip = 0.5 * pin.small_diameter();
  if (end.length > 0.0) {
    const double behind = tip + 0.5 * pin.taper() * end.length;
    meshes.inner = MakeClosedFrustum(0.5 * pin.large_diameter(), behind, -pin.length(),
                                     -end.length, facets);
    AppendMesh(MakeClosedFrustum(behind, tip - end.width(), -end.length, 0.0, facets),
               &meshes.inner);
  } else {
    meshes.inner = MakeClosedFrustum(0.5 * pin.large_diameter(), tip, -pin.length(), 0.0, facets);
  }
  const Chamfer& entrance = hole.chamfer();
  const double large = 0.5 * hole.large_diameter(), hub = 0.5 * hole.outer_diameter();
  meshes.outer = MakeTaperedTube(large, 0.5 * hole.small_diameter(), hub, 0.0, hole.length(), facets);
  if (entrance.length > 0.0) {
    AppendMesh(MakeTaperedTube(large + entrance.width(), large, hub, -entrance.length, 0.0, facets),
               &meshes.outer);
  }
  return meshes;
}

LeadIn MakeConicalLeadIn(const PartSpec& inner, const PartSpec& outer) {
  const ConicalGeometry& pin = GeometryOf(inner);
  const ConicalGeometry& hole = GeometryOf(outer);
  // Middle of the size zones: the small-end diameters are the toleranced sizes.
  const double slope = 0.5 * pin.taper();  // tan(alpha): radius per length
  const double tip = 0.5 * inner.size.mid_size();
  const double mouth = 0.5 * outer.size.mid_size() + slope * hole.length();
  const Chamfer& end = pin.chamfer();
  const Chamfer& entrance = hole.chamfer();
  RadiusProfile moving, fixed;
  moving.points.emplace_back(0.0, tip - end.width());
  if (end.length > 0.0) moving.points.emplace_back(end.length, tip + slope * end.length);
  moving.points.emplace_back(pin.length(), tip + slope * pin.length());
  fixed.points.emplace_back(0.0, mouth + entrance.width());
  if (entrance.length > 0.0) fixed.points.emplace_back(entrance.length, mouth);
  fixed.points.emplace_back(entrance.length + hole.length(), mouth - slope * hole.length());
  return LeadIn(moving, fixed, -entrance.length, end.length);
}

}  // namespace fitfeel::conical
