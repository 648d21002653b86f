#pragma once

#include <memory>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framework/collision/coarse_mesh.h"
#include "framework/core/export.h"

namespace fitfeel {

// Result of one collision query between a moving and a fixed coarse mesh, in the scene frame.
struct Penetration {
  bool contact = false;
  // Overlapping pairs of convex pieces, or triangle pairs FCL reported (at most max_contacts).
  int contacts = 0;
  // Penetration, m (0 when free): the overlap along `normal` (see MeshCollider).
  double depth = 0.0;
  // Unit direction in which the moving part must move to leave the fixed one (the chosen
  // contact's normal, turned to point from the fixed part to the moving one); zero when free.
  Eigen::Vector3d normal{0.0, 0.0, 0.0};
  // Where the force acts: the overlapping pieces' box intersections' centre (convex_pieces.h),
  // or a point of FCL's chosen contact.
  Eigen::Vector3d point{0.0, 0.0, 0.0};
};

class MeshCollider;

// What one query changes: the moving pieces placed and the overlaps found (sized for the pair up
// front), or FCL's request and its result with a contact buffer reserved up front. One scratch
// serves one thread at a time; a collider serves any number of them at once (see
// MeshCollider::MakeScratch).
class FITFEEL_API CollisionScratch {
 public:
  ~CollisionScratch();
  CollisionScratch(const CollisionScratch&) = delete;
  CollisionScratch& operator=(const CollisionScratch&) = delete;

 private:
  friend class MeshCollider;
  struct Impl;
  explicit CollisionScratch(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  const MeshCollider* owner_ = nullptr;
};

// Collision between a fixed and a moving coarse mesh, built once here and only read afterwards.
// Query is the per-tick path; what it changes lives in a CollisionScratch, so one collider serves
// several threads, each with its own scratch.
//
// Meshes made of convex solids (every shipped surface's: prisms, frustums, boxes, tubes as convex
// sectors) are taken as convex pieces and collided by separating axes (convex_pieces.h): each
// overlapping pair's overlap along every face normal of both pieces, and the way out of all of
// them along the summed and the deepest pairs' axes. positioning_tick_benchmark, the 20 mm pair
// in 50 facets, in contact: 8.4-8.5 us a query, where FCL's hierarchies take 190 us (a face) and
// 180 us (a tilted part in the bore), and FCL's own convex-convex test (GJK, libccd) 0.85 us a
// pair of pieces before its penetration depth (EPA), 43 us for the face's 50 sectors. The pieces'
// cost grows with the facets squared (each facet's sector against each face of the shaft): at
// 200 facets 0.11-0.12 ms, FCL's 0.12-0.48 ms.
//
// Other meshes go to FCL's mesh-mesh collision (OBBRSS bounding volume hierarchies). Depth: FCL
// reports, per intersecting triangle pair (fcl::detail::Intersect::intersect_Triangle),
// one triangle's plane normal and a depth through it; FCL has no mesh-mesh minimum translation.
// Query estimates the way out (see mesh_collider.cc): along each reported normal d it takes, per
// pair, the smaller of the plane bound (depth / cos) and the projection bound of the pair's two
// triangles on d, the largest of these over the pairs, and answers the normal where that is
// least. For a flat end struck on a flat face this is the exact interpenetration; for a part
// pressed sideways into a faceted wall it is the offset less the meshes' slack, to within their
// chordal error. It is an estimate: it sees only the first max_contacts pairs FCL finds and only
// the meshes' face normals as axes (no edge-edge axes), so for a tilted part it can overstate
// the way out.
class FITFEEL_API MeshCollider {
 public:
  // Throws UserError for an empty mesh, an index out of range or max_contacts < 1.
  MeshCollider(const TriangleMesh& fixed, const TriangleMesh& moving, int max_contacts = 64);
  ~MeshCollider();
  MeshCollider(const MeshCollider&) = delete;
  MeshCollider& operator=(const MeshCollider&) = delete;

  // A scratch for Query with its contact buffer reserved (prepare time: allocates).
  std::unique_ptr<CollisionScratch> MakeScratch() const;
  // Places the moving mesh at `moving_pose` (its frame in the scene frame) in `scratch` and
  // collides it with the fixed one. `scratch` must come from this collider's MakeScratch
  // (aborts otherwise). Does not allocate (the scratch's contact buffer has its capacity, see
  // mesh_collider.cc); noexcept: an FCL failure reports no contact.
  void Query(const Eigen::Isometry3d& moving_pose, CollisionScratch* scratch,
             Penetration* out) const noexcept;

  int max_contacts() const { return max_contacts_; }
  // True when both meshes are made of convex solids (connected components): queried by separating
  // axes (convex_pieces.h); otherwise by FCL's hierarchies.
  bool convex_pieces() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int max_contacts_ = 0;
};

}  // namespace fitfeel
