#include "framework/runtime/positioning_stage.h"

#include <cmath>
#include <limits>

#include "framework/collision/mesh_collider.h"
#include "framework/core/error.h"

namespace fitfeel {
namespace {

// Half a turn about z: (x, y, z) -> (-x, -y, z), a proper rotation, so triangles keep their
// outward winding.
TriangleMesh HalfTurnAboutZ(TriangleMesh mesh) {
  for (Eigen::Vector3d& v : mesh.vertices) {
    v.x() = -v.x();
    v.y() = -v.y();
  }
  return mesh;
}

struct PositioningState final : StageState {
  std::unique_ptr<CollisionScratch> scratch;  // null without coarse meshes
  // The god object (lead-in): where the part was on the last positioning tick, in (y, r), and the
  // direction of its offset (kept while the device is on the axis).
  bool has_part = false;
  Eigen::Vector2d part{0.0, 0.0};
  Eigen::Vector2d direction{1.0, 0.0};
};

}  // namespace

double FreeMotionStiffness(double contact_stiffness, double device_max_stiffness) {
  if (!(contact_stiffness >= 0.0) || !std::isfinite(contact_stiffness) ||
      !(device_max_stiffness >= 0.0)) {
    throw UserError(
        "free-motion stiffness: the contact stiffness must be finite and >= 0, the device's "
        "largest stable stiffness >= 0");
  }
  // 0 or infinity: the device states no limit (a simulated device integrates implicitly).
  const bool limited = device_max_stiffness > 0.0 && std::isfinite(device_max_stiffness);
  // A contact stiffness of 0 (`auto`: the law's own elastic model, far stiffer than any device)
  // leaves the device's limit as the stiffest wall it can be shown.
  if (contact_stiffness == 0.0) return limited ? device_max_stiffness : 0.0;
  if (limited && contact_stiffness > device_max_stiffness) return device_max_stiffness;
  return contact_stiffness;
}

PositioningStage::PositioningStage() : PositioningStage(Options{}) {}

PositioningStage::PositioningStage(const Options& options) : options_(options) {
  if (!(options.alignment_tolerance >= 0.0) || !(options.alignment_tolerance < M_PI / 2)) {
    throw UserError("positioning stage: alignment tolerance must be in [0, 90) degrees");
  }
  if (!(options.capture_radius >= 0.0) || !std::isfinite(options.capture_radius)) {
    throw UserError("positioning stage: capture radius must be a finite length >= 0");
  }
  if (!(options.free_stiffness >= 0.0) || !std::isfinite(options.free_stiffness)) {
    throw UserError("positioning stage: free-motion stiffness must be finite and >= 0");
  }
  if (options.max_contacts < 1) {
    throw UserError("positioning stage: max_contacts must be >= 1");
  }
  cos_alignment_tolerance_ = std::cos(options.alignment_tolerance);
}

PositioningStage::PositioningStage(const Options& options, const CoarseMeshes& meshes, Role moving)
    : PositioningStage(options) {
  if (meshes.empty()) return;
  if (moving == Role::kInner) {
    collider_ = std::make_unique<MeshCollider>(meshes.outer, meshes.inner, options.max_contacts);
  } else {
    collider_ = std::make_unique<MeshCollider>(HalfTurnAboutZ(meshes.inner),
                                               HalfTurnAboutZ(meshes.outer), options.max_contacts);
  }
}

PositioningStage::PositioningStage(const Options& options, const CoarseMeshes& meshes, Role moving,
                                   LeadIn lead_in)
    // A lead-in takes the meshes' place: their collider is not built.
    : PositioningStage(options, lead_in.empty() ? meshes : CoarseMeshes{}, moving) {
  lead_in_ = std::move(lead_in);
}

PositioningStage::~PositioningStage() = default;

std::unique_ptr<StageState> PositioningStage::DoMakeState() const {
  auto state = std::make_unique<PositioningState>();
  if (collider_ != nullptr) state->scratch = collider_->MakeScratch();
  return state;
}

void PositioningStage::DoEvaluate(const PartState& part, StageState* state,
                                  StageOutput* out) const noexcept {
  if (!lead_in_.empty()) {
    GuideThroughLeadIn(part, state, out);
    return;
  }
  out->wrench.SetZero();
  out->pose = MatingPoseOf(part);
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  out->stiffness = 0.0;
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  const Eigen::Quaterniond orientation = part.orientation.normalized();
  // cos(tilt) is the y component of the part's axis (the orientation's y column).
  const double cos_tilt = orientation.toRotationMatrix()(1, 1);
  const bool aligned = cos_tilt >= cos_alignment_tolerance_;
  const bool captured = out->pose.offset.norm() <= options_.capture_radius;
  const bool entered = out->pose.depth >= 0.0;
  out->next = (entered && aligned && captured) ? StageId::kConstrained : StageId::kPositioning;
  if (collider_ == nullptr || out->next == StageId::kConstrained) return;
  if (!part.position.allFinite() || !orientation.coeffs().allFinite()) return;

  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = orientation.toRotationMatrix();
  pose.translation() = part.position;
  Penetration penetration;
  collider_->Query(pose, static_cast<PositioningState*>(state)->scratch.get(), &penetration);
  if (!penetration.contact || !(penetration.depth > 0.0)) return;
  const double k = options_.free_stiffness;
  out->wrench.force = k * penetration.depth * penetration.normal;
  // About the leading end, the point whose pose the device reports.
  out->wrench.torque = (penetration.point - part.position).cross(out->wrench.force);
  out->stiffness = k;
}

void PositioningStage::GuideThroughLeadIn(const PartState& held_part, StageState* state,
                                          StageOutput* out) const noexcept {
  auto* run = static_cast<PositioningState*>(state);
  const double origin = lead_in_.capture_depth();
  // Handed back by the constrained stage: the part is where that stage left it.
  if (out->stage != StageId::kPositioning) {
    run->part = Eigen::Vector2d(out->pose.depth + origin, lead_in_.Extent(out->pose.offset));
    run->has_part = true;
  }
  const MatingPose held = MatingPoseOf(held_part);
  out->pose = held;
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  out->wrench.SetZero();
  out->stiffness = 0.0;
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  out->next = StageId::kPositioning;
  if (!held_part.position.allFinite()) return;
  const double held_r = lead_in_.Extent(held.offset);
  if (held.offset.norm() > 0.0) run->direction = held.offset.normalized();
  const Eigen::Vector2d target(held_part.position.y(), held_r);
  const Eigen::Vector2d part = lead_in_.Project(target, run->has_part ? run->part : target);
  run->part = part;
  run->has_part = true;
  out->pose.depth = part.x() - origin;
  out->pose.offset = lead_in_.Place(held.offset, part.y(), run->direction);
  const double k = options_.free_stiffness;
  if (part != target) {
    // The spring between the device and the part: along the axis and across it.
    out->wrench.force = k * Eigen::Vector3d(out->pose.offset.x() - held.offset.x(),
                                            part.x() - target.x(),
                                            out->pose.offset.y() - held.offset.y());
    out->stiffness = k;
  }
  // Past the capture depth (an interference fit: at it, where the part wedges and stops), so
  // that the constrained stage's first tick has some engagement.
  if (part.x() > origin || (lead_in_.play() < 0.0 && part.x() >= origin)) {
    out->next = StageId::kConstrained;
  }
}

}  // namespace fitfeel
