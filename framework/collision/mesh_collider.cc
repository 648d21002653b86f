#include "framework/collision/mesh_collider.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>

#include "framework/collision/convex_pieces.h"
#include "framework/core/demand.h"
#include "framework/core/error.h"

namespace fitfeel {
namespace {

using Bvh = fcl::BVHModel<fcl::OBBRSSd>;

void CheckMesh(const TriangleMesh& mesh, const char* which) {
  if (mesh.empty()) throw UserError(std::string("mesh collider: the ") + which + " mesh is empty");
  const int n = static_cast<int>(mesh.vertices.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    if (t.minCoeff() < 0 || t.maxCoeff() >= n) {
      throw UserError(std::string("mesh collider: the ") + which +
                      " mesh has a vertex index out of range");
    }
  }
  for (const Eigen::Vector3d& v : mesh.vertices) {
    if (!v.allFinite()) {
      throw UserError(std::string("mesh collider: the ") + which + " mesh has a vertex not finite");
    }
  }
}

std::shared_ptr<Bvh> BuildBvh(const TriangleMesh& mesh, const char* which) {
  std::vector<fcl::Vector3d> points(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<Bvh>();
  if (model->beginModel() != fcl::BVH_OK || model->addSubModel(points, triangles) != fcl::BVH_OK ||
      model->endModel() != fcl::BVH_OK) {
    throw UserError(std::string("mesh collider: FCL refused the ") + which + " mesh");
  }
  return model;
}

}  // namespace

// Immutable after construction, only read by queries: the meshes as convex pieces when both are
// made of convex solids, else FCL's hierarchies. FCL's queries go through its
// geometry-and-transform overload of collide: a CollisionObject would hold the pose (state of a
// run) and recompute the shared geometry's local bounding box whenever one is made.
struct MeshCollider::Impl {
  Impl(const TriangleMesh& fixed_mesh, const TriangleMesh& moving_mesh) {
    CheckMesh(fixed_mesh, "fixed");
    CheckMesh(moving_mesh, "moving");
    std::optional<std::vector<ConvexPiece>> f = ConvexPieces(fixed_mesh);
    std::optional<std::vector<ConvexPiece>> m = f ? ConvexPieces(moving_mesh) : std::nullopt;
    if (f && m) {
      fixed_pieces = std::move(*f);
      moving_pieces = std::move(*m);
      return;
    }
    fixed_vertices = fixed_mesh.vertices;
    fixed_triangles = fixed_mesh.triangles;
    moving_vertices = moving_mesh.vertices;
    moving_triangles = moving_mesh.triangles;
    fixed = BuildBvh(fixed_mesh, "fixed");
    moving = BuildBvh(moving_mesh, "moving");
    fixed->computeLocalAABB();
    moving->computeLocalAABB();
  }
  bool pieces() const { return !fixed_pieces.empty(); }
  std::vector<ConvexPiece> fixed_pieces, moving_pieces;
  // The meshes again, for the separating-axis projections (FCL reports triangle indices).
  std::vector<Eigen::Vector3d> fixed_vertices;
  std::vector<Eigen::Vector3i> fixed_triangles;
  std::vector<Eigen::Vector3d> moving_vertices;
  std::vector<Eigen::Vector3i> moving_triangles;
  std::shared_ptr<Bvh> fixed;
  std::shared_ptr<Bvh> moving;
};

struct CollisionScratch::Impl {
  // With FCL (`contacts` > 0) its request and result; the pieces' scratch is reserved by
  // MakeScratch.
  explicit Impl(int contacts) : request(std::max(contacts, 1), /*enable_contact=*/true) {
    // The contact buffer the query fills, grown here so that the tick only reuses it: the vector
    // is private to FCL, but clear() keeps its capacity, so filling it once reserves it.
    for (int i = 0; i < contacts; ++i) result.addContact(fcl::Contactd());
    result.clear();
  }
  ConvexPiecesScratch pieces;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
};

CollisionScratch::CollisionScratch(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

CollisionScratch::~CollisionScratch() = default;

MeshCollider::MeshCollider(const TriangleMesh& fixed, const TriangleMesh& moving,
                           int max_contacts) {
  if (max_contacts < 1) throw UserError("mesh collider: max_contacts must be >= 1");
  max_contacts_ = max_contacts;
  impl_ = std::make_unique<Impl>(fixed, moving);
}

MeshCollider::~MeshCollider() = default;

bool MeshCollider::convex_pieces() const { return impl_->pieces(); }

std::unique_ptr<CollisionScratch> MeshCollider::MakeScratch() const {
  std::unique_ptr<CollisionScratch> scratch(new CollisionScratch(
      std::make_unique<CollisionScratch::Impl>(impl_->pieces() ? 0 : max_contacts_)));
  if (impl_->pieces()) scratch->impl_->pieces.Reserve(impl_->moving_pieces, impl_->fixed_pieces);
  scratch->owner_ = this;
  return scratch;
}

void MeshCollider::Query(const Eigen::Isometry3d& moving_pose, CollisionScratch* scratch,
                         Penetration* out) const noexcept {
  FITFEEL_DEMAND(out != nullptr);
  FITFEEL_DEMAND(scratch != nullptr && scratch->owner_ == this);
  *out = Penetration{};
  const Impl& impl = *impl_;
  CollisionScratch::Impl& query = *scratch->impl_;
  if (impl.pieces()) {
    out->contacts = PenetrationOfPieces(impl.moving_pieces, impl.fixed_pieces, moving_pose,
                                        &query.pieces, &out->depth, &out->normal, &out->point);
    out->contact = out->contacts > 0;
    return;
  }
  // clear() keeps the contact vector's capacity: collide's push_backs then reuse the buffer.
  query.result.clear();
  try {
    fcl::collide<double>(impl.moving.get(), moving_pose, impl.fixed.get(),
                         fcl::Transform3d::Identity(), query.request, query.result);
  } catch (...) {
    return;  // FCL does not throw on this path; never let anything escape the tick
  }
  const fcl::CollisionResultd& result = query.result;
  const std::size_t n = result.numContacts();
  if (n == 0) return;
  out->contact = true;
  out->contacts = static_cast<int>(n);
  const Eigen::Matrix3d rotation = moving_pose.linear();
  const Eigen::Vector3d translation = moving_pose.translation();
  // The way out: every contact j is a pair of intersecting triangles with FCL's depth p_j along
  // its normal n_j (turned to point from the fixed part to the moving one). Moving the part by t
  // along a unit axis d separates pair j once t >= r_j(d), where r_j(d) is the smaller of two
  // sufficient bounds: the plane bound p_j / (n_j . d) (the pair's triangle leaves the other's
  // plane; none when n_j . d <= 0), and the projection bound max f.d - min m.d over the pair's
  // two triangles (their projections on d part). The axes tried are the reported normals, and the
  // answer is the axis of least max_j r_j(d). Neither the deepest pair (long wall triangles
  // crossing a face lie millimetres through each other's planes while the parts overlap by
  // micrometres along y) nor a per-axis deepest pair (a pair grazing a wall understates the
  // overlap along its normal) nor projections alone (a wall overlapped over half its
  // circumference) gives the way out; the two bounds together do for faces and faceted walls.
  constexpr double kSameDirection = 1.0 - 1e-9;  // cos of ~45 urad
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  std::size_t best = 0;
  double best_overlap = kInfinity;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d axis = -result.getContact(i).normal.normalized();
    if (!axis.allFinite()) continue;
    bool seen = false;  // an earlier contact already tried this axis
    for (std::size_t j = 0; j < i && !seen; ++j) {
      seen = result.getContact(j).normal.normalized().dot(-axis) >= kSameDirection;
    }
    if (seen) continue;
    // Moving vertices are in the moving frame: m.d = m_local.(R^T d) + t.d.
    const Eigen::Vector3d local_axis = rotation.transpose() * axis;
    const double offset = translation.dot(axis);
    double required = 0.0;
    for (std::size_t j = 0; j < n && required < best_overlap; ++j) {
      const fcl::Contactd& c = result.getContact(j);
      const double cosine = -c.normal.normalized().dot(axis);
      const double plane = cosine > 1e-12 ? c.penetration_depth / cosine : kInfinity;
      const Eigen::Vector3i& ft = impl.fixed_triangles[static_cast<std::size_t>(c.b2)];
      const Eigen::Vector3i& mt = impl.moving_triangles[static_cast<std::size_t>(c.b1)];
      double fixed_max = -kInfinity;
      double moving_min = kInfinity;
      for (int k = 0; k < 3; ++k) {
        fixed_max = std::max(fixed_max, impl.fixed_vertices[ft[k]].dot(axis));
        moving_min = std::min(moving_min, impl.moving_vertices[mt[k]].dot(local_axis) + offset);
      }
      required = std::max(required, std::min(plane, fixed_max - moving_min));
    }
    if (required < best_overlap) {
      best_overlap = required;
      best = i;
    }
  }
  const fcl::Contactd& c = result.getContact(best);
  const Eigen::Vector3d normal = -c.normal.normalized();
  out->point = c.pos;
  // Touching (no overlap along some axis) or no usable normal: in contact, but nothing to push.
  if (!(best_overlap > 0.0) || !std::isfinite(best_overlap) || !normal.allFinite()) return;
  out->depth = best_overlap;
  // FCL's normal points from o1 (the moving part) to o2 (the fixed one); ours the other way.
  out->normal = normal;
}

}  // namespace fitfeel
