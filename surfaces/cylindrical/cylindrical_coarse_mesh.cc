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
  meshes.inner = MakeClosedCylinder(radius, -shaft.length(), 0.0, facets);
  meshes.outer =
      MakeTube(0.5 * hole.diameter(), 0.5 * hole.outer_diameter(), 0.0, hole.length(), facets);
  return meshes;
}

}  // namespace fitfeel::cylindrical
