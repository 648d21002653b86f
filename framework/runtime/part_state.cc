#include "framework/runtime/part_state.h"

#include <cmath>

namespace fitfeel {

MatingPose MatingPoseOf(const PartState& part) noexcept {
  MatingPose pose;
  pose.depth = part.position.y();
  pose.offset = Eigen::Vector2d(part.position.x(), part.position.z());
  // Swing-twist decomposition: the twist about y of q = (w, x, y, z) is 2 atan2(y, w).
  const Eigen::Quaterniond& q = part.orientation;
  pose.angle = 2.0 * std::atan2(q.y(), q.w());
  if (pose.angle > M_PI) pose.angle -= 2.0 * M_PI;
  if (pose.angle < -M_PI) pose.angle += 2.0 * M_PI;
  return pose;
}

}  // namespace fitfeel
