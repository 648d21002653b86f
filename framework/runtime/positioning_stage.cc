#include "framework/runtime/positioning_stage.h"

#include <cmath>
#include <limits>

#include "framework/core/error.h"

namespace fitfeel {

MatingPose MatingPoseOf(const DeviceState& device) noexcept {
  MatingPose pose;
  pose.depth = device.position.y();
  pose.offset = Eigen::Vector2d(device.position.x(), device.position.z());
  // Swing-twist decomposition: the twist about y of q = (w, x, y, z) is 2 atan2(y, w).
  const Eigen::Quaterniond& q = device.orientation;
  pose.angle = 2.0 * std::atan2(q.y(), q.w());
  if (pose.angle > M_PI) pose.angle -= 2.0 * M_PI;
  if (pose.angle < -M_PI) pose.angle += 2.0 * M_PI;
  return pose;
}

PositioningStage::PositioningStage() : PositioningStage(Options{}) {}

PositioningStage::PositioningStage(const Options& options) : options_(options) {
  if (!(options.alignment_tolerance >= 0.0) || !(options.alignment_tolerance < M_PI / 2)) {
    throw UserError("positioning stage: alignment tolerance must be in [0, 90) degrees");
  }
  if (!(options.capture_radius >= 0.0) || !std::isfinite(options.capture_radius)) {
    throw UserError("positioning stage: capture radius must be a finite length >= 0");
  }
  cos_alignment_tolerance_ = std::cos(options.alignment_tolerance);
}

void PositioningStage::DoEvaluate(const DeviceState& device, StageOutput* out) const noexcept {
  out->wrench.SetZero();
  out->pose = MatingPoseOf(device);
  out->contact = ContactState{};
  out->stiffness = 0.0;
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  // cos(tilt) is the y component of the part's axis (the orientation's y column).
  const double cos_tilt = device.orientation.normalized().toRotationMatrix()(1, 1);
  const bool aligned = cos_tilt >= cos_alignment_tolerance_;
  const bool captured = out->pose.offset.norm() <= options_.capture_radius;
  const bool entered = out->pose.depth >= 0.0;
  out->next = (entered && aligned && captured) ? StageId::kConstrained : StageId::kPositioning;
}

}  // namespace fitfeel
