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
    // In front of the mating surface, as the lead-in has it (MakeCylindricalLeadIn).
    meshes.outer =
        MakeTaperedTube(bore + entrance.width(), bore, hub, -entrance.length, 0.0, facets);
    AppendMesh(MakeTube(bore, hub, 0.0, hole.length(), facets), &meshes.outer);
  } else {
    meshes.outer = MakeTube(bore, hub, 0.0, hole.length(), facets);
  }
  return meshes;
}

LeadIn MakeCylindricalLeadIn(const PartSpec& inner, const PartSpec& outer) {
  const double shaft = 0.5 * inner.size.mid_size(), bore = 0.5 * outer.size.mid_size();
  const Chamfer& end = GeometryOf(inner).chamfer();
  const Chamfer& entrance = GeometryOf(outer).chamfer();
  RadiusProfile moving, fixed;
  moving.points.emplace_back(0.0, shaft - end.width());
  if (end.length > 0.0) moving.points.emplace_back(end.length, shaft);
  fixed.points.emplace_back(0.0, bore + entrance.width());
  if (entrance.length > 0.0) fixed.points.emplace_back(entrance.length, bore);
  return LeadIn(moving, fixed, -entrance.length, end.length);
}

}  // namespace fitfeel::cylindrical
