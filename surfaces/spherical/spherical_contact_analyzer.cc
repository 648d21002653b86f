#include "surfaces/spherical/spherical_contact_analyzer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fitfeel::spherical {

void SphericalContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                         const PartSpec& outer, const SkinModelShape& outer_sms,
                                         const ModelSettings& settings) {
  scan_.Prepare(inner, inner_sms, outer, outer_sms, settings);
  const int entries = scan_.columns() * kStepsPerColumn;
  const double step = 2.0 * M_PI / entries;
  // A run whose device turns the ball by at most ModelSettings::angular_reach either way needs no
  // entry past it (a bearing's swing of 15 degrees: 13 of 144 steps); two steps more cover the
  // blend's next entry and the turn as read back from the device. Each entry is the whole
  // table's bits.
  std::vector<int> wanted;
  const double reach = std::ceil(settings.angular_reach / step) + 2.0;
  if (2.0 * reach + 1.0 < entries) {
    const int r = static_cast<int>(reach);
    for (int q = 0; q <= r; ++q) wanted.push_back(q);
    for (int q = entries - r; q < entries; ++q) wanted.push_back(q);
  }
  Tabulate(entries, step, wanted);
}

void SphericalContactAnalyzer::DoEvaluate(const MatingPose& pose,
                                          ContactState* out) const noexcept {
  *out = ContactState{};
  if (!std::isfinite(pose.angle) || !pose.offset.allFinite()) return;
  out->engaged = true;
  out->engaged_length = scan_.width();
  out->engaged_area = scan_.engaged_area();
  out->offset_distance = pose.offset.norm();
  out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
  const int entries = steps();
  double u = std::fmod(pose.angle / step(), static_cast<double>(entries));
  if (u < 0.0) u += entries;
  const int q = std::min(static_cast<int>(u), entries - 1);
  const double t = u - q;
  const int q1 = q + 1 == entries ? 0 : q + 1;
  Blend(q, q1, t, pose, 0.0, out);
}

}  // namespace fitfeel::spherical
