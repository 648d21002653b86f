#include "surfaces/cylindrical/cylindrical_coarse_mesh.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"

namespace fitfeel::cylindrical {
namespace {

const CylindricalGeometry& GeometryOf(const PartSpec& part) {
  const auto* geometry = dynamic_cast<const CylindricalGeometry*>(part.geometry.get());
  if (geometry == nullptr) {
    throw UserError("coarse mesh: part '" + part.name + "' has no cylindrical geometry");
  }
  return *geometry;
}

double Zone(const PartSpec& part) {
  return std::abs(part.size.upper_deviation - part.size.lower_deviation);
}

}  // namespace

int CoarseFacets(const PartSpec& inner, const PartSpec& outer) {
  const double radius = 0.5 * GeometryOf(inner).diameter();
  const double radial_zone = 0.5 * (Zone(inner) + Zone(outer));
  // Exact parts (zero tolerance) get the finest mesh offered.
  if (!(radial_zone > 0.0)) return kMaxCoarseFacets;
  const double finest = ChordalError(radius, kMaxCoarseFacets);
  return std::min(kMaxCoarseFacets, FacetsForChordalError(radius, std::max(radial_zone, finest)));
}

CoarseMeshes MakeCylindricalCoarseMeshes(const PartSpec& inner, const PartSpec& outer) {
  const CylindricalGeometry& shaft = GeometryOf(inner);
  const CylindricalGeometry& hole = GeometryOf(outer);
  const int facets = CoarseFacets(inner, outer);
  const double radius = 0.5 * shaft.diameter();
  CoarseMeshes meshes;
  // The lead-in chamfers, as frustums: the shaft's end narrows toward its tip, the bore widens
  // toward its entrance, so that a part pushed off the axis meets a slope that turns it in.
  const Chamfer& end = shaft.chamfer();
  if (end.length > 0.0) {
    meshes.inner = MakeClosedCylinder(radius, -shaft.length(), -end.length, facets);
    AppendMesh(MakeClosedFrustum(radius, radius - end.width(), -end.length, 0.0, facets),
               &meshes.inner);
  } else {
    meshes.inner = MakeClosedCylinder(radius, -shaft.length(), 0.0, facets);
  }
  const double bore = 0.5 * hole.diameter(), hub = 0.5 * hole.outer_diameter();
  const Chamfer& entrance = hole.chamfer();
  if (entrance.length > 0.0) {
    meshes.outer = MakeTaperedTube(bore + entrance.width(), bore, hub, 0.0, entrance.length, facets);
    AppendMesh(MakeTube(bore, hub, entrance.length, hole.length(), facets), &meshes.outer);
  } else {
    meshes.outer = MakeTube(bore, hub, 0.0, hole.length(), facets);
  }
  return meshes;
}

}  // namespace fitfeel::cylindrical
