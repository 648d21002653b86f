#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framework/core/export.h"

namespace fitfeel {

// A closed triangle mesh in a part's own frame (m). Triangles list vertex indices counter-clockwise
// seen from outside the solid, so that normals point out of the material.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  bool empty() const { return triangles.empty(); }
};

// The coarse meshes of a mating pair for free-motion collision (docs/architecture.md, section 4:
// only mating surfaces get a skin model shape; the rest of a part is a coarse mesh for
// MeshCollider, which takes a mesh made of convex solids, its connected components, as convex
// pieces, and any other to FCL). Each is in the scene's mating frame as it would be were the
// inner part the moving one:
//  - inner: the moving part's frame, its leading end at the origin, its axis +y (the direction of
//    insertion), so its body lies at y <= 0;
//  - outer: the fixed part's frame, its entrance at y = 0, its body at y >= 0.
// When the outer part moves instead, the positioning stage turns both meshes half a turn about z,
// which puts each in the convention for its new role. Both empty: the surface type models no
// collision in free motion (the part passes through the other without resistance until mating).
struct CoarseMeshes {
  TriangleMesh inner;
  TriangleMesh outer;
  bool empty() const { return inner.empty() || outer.empty(); }
};

// Facets of a regular polygon inscribed in a circle of `radius` whose chordal error (radius minus
// the apothem, r (1 - cos(pi / n))) is at most `max_chordal_error`; at least 8, so that a
// polygon stays a fair stand-in for a circle even for a coarse bound. Throws UserError for a
// non-positive or non-finite argument or when more than 4096 facets would be needed.
FITFEEL_API int FacetsForChordalError(double radius, double max_chordal_error);

// Chordal error r (1 - cos(pi / n)) of an n-gon inscribed in a circle of `radius`.
FITFEEL_API double ChordalError(double radius, int facets);

// A closed prism of `facets` sides about the y axis, its vertices on the circle of `radius`,
// from y = y0 to y = y1 (y0 < y1), with one end cap at each end. The first vertex of each ring is
// at angle 0 (on +x). Throws UserError for bad dimensions or fewer than 3 facets.
FITFEEL_API TriangleMesh MakeClosedCylinder(double radius, double y0, double y1, int facets);

// A closed tube about the y axis from y = y0 to y = y1: its outer wall's vertices on the circle
// of `outer_radius`, its inner wall a polygon whose facets are tangent to the circle of
// `inner_radius` (its vertices at inner_radius / cos(pi / n), first at angle 0), so that the
// tube's material lies wholly outside that circle; annular faces at both ends. Made of one closed,
// convex sector per facet (eight corners each: the bore's facet, the outer facet, the two planes
// through the axis at the facet's ends), so that a collider can take it as convex pieces. Throws
// UserError for bad dimensions (the inner polygon must fit inside the outer one).
FITFEEL_API TriangleMesh MakeTube(double inner_radius, double outer_radius, double y0, double y1,
                                  int facets);

// A closed frustum about the y axis: vertices on the circle of `radius0` at y0 and `radius1` at
// y1, end caps at both ends (a cone's pin, a chamfered end). Throws UserError as the cylinder.
FITFEEL_API TriangleMesh MakeClosedFrustum(double radius0, double radius1, double y0, double y1,
                                           int facets);

// A tube as MakeTube whose bore's facets are tangent to the circle of `inner_radius0` at y0 and
// `inner_radius1` at y1 (a taper-reamed hole, a chamfered entrance).
FITFEEL_API TriangleMesh MakeTaperedTube(double inner_radius0, double inner_radius1,
                                         double outer_radius, double y0, double y1, int facets);

// A closed axis-aligned box from `low` to `high`. Throws UserError unless low < high on every axis.
FITFEEL_API TriangleMesh MakeBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high);

// Appends `part`'s vertices and triangles to `mesh` (several closed solids in one mesh).
FITFEEL_API void AppendMesh(const TriangleMesh& part, TriangleMesh* mesh);

}  // namespace fitfeel
