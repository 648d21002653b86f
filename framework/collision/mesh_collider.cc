#include "framework/collision/mesh_collider.h"

#include <string>
#include <vector>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

using Bvh = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Bvh> BuildBvh(const TriangleMesh& mesh, const char* which) {
  if (mesh.empty()) throw UserError(std::string("mesh collider: the ") + which + " mesh is empty");
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<fcl::Vector3d> points(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    if (t.minCoeff() < 0 || t.maxCoeff() >= n) {
      throw UserError(std::string("mesh collider: the ") + which +
                      " mesh has a vertex index out of range");
    }
    triangles.emplace_back(t[0], t[1], t[2]);
  }
  auto model = std::make_shared<Bvh>();
  if (model->beginModel() != fcl::BVH_OK || model->addSubModel(points, triangles) != fcl::BVH_OK ||
      model->endModel() != fcl::BVH_OK) {
    throw UserError(std::string("mesh collider: FCL refused the ") + which + " mesh");
  }
  return model;
}

}  // namespace

struct MeshCollider::Impl {
  Impl(std::shared_ptr<Bvh> fixed_model, std::shared_ptr<Bvh> moving_model, int max_contacts)
      : fixed(fixed_model), moving(moving_model), request(max_contacts, /*enable_contact=*/true) {
    // The contact buffer the query fills, grown here so that the tick only reuses it: the vector
    // is private to FCL, but clear() keeps its capacity, so filling it once reserves it.
    for (int i = 0; i < max_contacts; ++i) result.addContact(fcl::Contactd());
    result.clear();
  }
  fcl::CollisionObjectd fixed;
  fcl::CollisionObjectd moving;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
};

MeshCollider::MeshCollider(const TriangleMesh& fixed, const TriangleMesh& moving,
                           int max_contacts) {
  if (max_contacts < 1) throw UserError("mesh collider: max_contacts must be >= 1");
  max_contacts_ = max_contacts;
  impl_ =
      std::make_unique<Impl>(BuildBvh(fixed, "fixed"), BuildBvh(moving, "moving"), max_contacts);
}

MeshCollider::~MeshCollider() = default;

void MeshCollider::Query(const Eigen::Isometry3d& moving_pose, Penetration* out) const noexcept {
  *out = Penetration{};
  Impl& impl = *impl_;
  impl.moving.setTransform(moving_pose);
  // clear() keeps the contact vector's capacity: collide's push_backs then reuse the buffer.
  impl.result.clear();
  try {
    fcl::collide(&impl.moving, &impl.fixed, impl.request, impl.result);
  } catch (...) {
    return;  // FCL does not throw on this path; never let anything escape the tick
  }
  const std::size_t n = impl.result.numContacts();
  if (n == 0) return;
  out->contact = true;
  out->contacts = static_cast<int>(n);
  std::size_t deepest = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (impl.result.getContact(i).penetration_depth >
        impl.result.getContact(deepest).penetration_depth) {
      deepest = i;
    }
  }
  const fcl::Contactd& c = impl.result.getContact(deepest);
  out->depth = c.penetration_depth > 0.0 ? c.penetration_depth : 0.0;
  // FCL's normal points from o1 (the moving part) to o2 (the fixed one).
  out->normal = -c.normal.normalized();
  out->point = c.pos;
}

}  // namespace fitfeel
