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
  int contacts = 0;  // triangle pairs FCL reported (at most the collider's max_contacts)
  // Penetration, m (0 when free): the overlap along `normal` (see MeshCollider).
  double depth = 0.0;
  // Unit direction in which the moving part must move to leave the fixed one (the chosen
  // contact's normal, turned to point from the fixed part to the moving one); zero when free.
  Eigen::Vector3d normal{0.0, 0.0, 0.0};
  Eigen::Vector3d point{0.0, 0.0, 0.0};  // a point of the chosen contact (FCL's contact position)
};

// FCL mesh-mesh collision between a fixed and a moving coarse mesh (OBBRSS bounding volume
// hierarchies, built once here). Query is the per-tick path: it keeps one pre-reserved FCL
// result and request and is therefore not re-entrant; one collider serves one tick thread.
//
// Depth: FCL reports, per intersecting triangle pair (fcl::detail::Intersect::intersect_Triangle),
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

  // Places the moving mesh at `moving_pose` (its frame in the scene frame) and collides it with
  // the fixed one. Does not allocate once the result's contact buffer has its capacity (see
  // mesh_collider.cc); noexcept: an FCL failure reports no contact.
  void Query(const Eigen::Isometry3d& moving_pose, Penetration* out) const noexcept;

  int max_contacts() const { return max_contacts_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int max_contacts_ = 0;
};

}  // namespace fitfeel
