#include "framework/runtime/joint_lead_in.h"

#include <cmath>

namespace fitfeel {
namespace {

// The unit direction across the axis in which the part's extent grows (LeadIn::Section).
Eigen::Vector2d Outward(LeadIn::Section section, const Eigen::Vector2d& offset) {
  const auto sign = [](double v) { return v < 0.0 ? -1.0 : 1.0; };
  switch (section) {
    case LeadIn::Section::kAcrossX:
      return {sign(offset.x()), 0.0};
    case LeadIn::Section::kSquare:
      return std::abs(offset.x()) >= std::abs(offset.y()) ? Eigen::Vector2d(sign(offset.x()), 0.0)
                                                          : Eigen::Vector2d(0.0, sign(offset.y()));
    case LeadIn::Section::kRound:
    default: {
      const double n = offset.norm();
      return n > 0.0 ? Eigen::Vector2d(offset / n) : Eigen::Vector2d(1.0, 0.0);
    }
  }
}

}  // namespace

LeadInPush PushOfLeadIn(const LeadIn& lead_in, double y, const Eigen::Vector2d& offset,
                        double stiffness) noexcept {
  LeadInPush push;
  const auto& b = lead_in.boundary();
  if (lead_in.empty() || b.size() < 3 || !(stiffness > 0.0)) return push;
  const double r = lead_in.Extent(offset);
  const double r_max = lead_in.MaxOffset(y);
  if (!(r > r_max)) return push;
  push.touching = true;
  // boundary[0] -> [1] is the entrance face, from its outer end in to the chamfer's outer edge.
  const double face = b[0].x();
  if (r > b[1].y()) {
    push.axial = -stiffness * (y - face);
    return push;
  }
  // The chamfer's segment at y (y past the boundary's end: its last segment).
  std::size_t i = 1;
  while (i + 2 < b.size() && y > b[i + 1].x()) ++i;
  const Eigen::Vector2d d = b[i + 1] - b[i];
  const double length = d.norm();
  if (!(length > 0.0)) return push;
  // The normal into the fixed part, (y, r) components: the chamfer falls (dr < 0) as y grows.
  const double n_y = -d.y() / length, n_r = d.x() / length;
  const double depth = (r - r_max) * n_r;
  push.axial = -stiffness * depth * n_y;
  push.across = -stiffness * depth * n_r * Outward(lead_in.section(), offset);
  return push;
}

}  // namespace fitfeel
