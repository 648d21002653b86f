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
  // The swing, q times the twist's inverse, has no y part: its rotation vector is the tilt.
  const Eigen::Quaterniond twist(std::cos(0.5 * pose.angle), 0.0, std::sin(0.5 * pose.angle), 0.0);
  Eigen::Quaterniond swing = q * twist.conjugate();
  if (swing.w() < 0.0) swing.coeffs() = -swing.coeffs();
  const double half = std::atan2(std::hypot(swing.x(), swing.z()), swing.w());
  const double scale = half > 1e-12 ? 2.0 * half / std::sin(half) : 2.0;
  pose.tilt = Eigen::Vector2d(swing.x(), swing.z()) * scale;
  return pose;
}

}  // namespace fitfeel
