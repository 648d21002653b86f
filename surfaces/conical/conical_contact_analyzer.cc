#include "surfaces/conical/conical_contact_analyzer.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace fitfeel::conical {
namespace {

// Beyond this many depth steps a finer model.depth_step only costs memory: 20000 steps of 72
// columns hold 380 MB.
constexpr double kMaxDepthSteps = 20000;

}  // namespace

void ConicalContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                       const PartSpec& outer, const SkinModelShape& outer_sms,
                                       const ModelSettings& settings) {
  scan_.Prepare(inner, inner_sms, outer, outer_sms, settings);
  const double range = scan_.pin_length() + scan_.hole_length();
  const double spacing = settings.depth_step > 0.0
                             ? settings.depth_step
                             : 0.5 * std::min(scan_.pin_pitch(), scan_.hole_pitch());
  if (!(range / spacing <= kMaxDepthSteps)) {
    throw UserError("conical contact table: a depth step of " + std::to_string(spacing * 1e3) +
                    " mm over " + std::to_string(range * 1e3) + " mm is more than " +
                    std::to_string(static_cast<int>(kMaxDepthSteps)) + " steps; take a coarser "
                    "model.depth_step");
  }
  const int last_step = std::max(1, static_cast<int>(std::ceil(range / spacing - 1e-9)));
  Tabulate(last_step + 1, spacing);
}

void ConicalContactAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  if (!std::isfinite(pose.depth) || !pose.offset.allFinite()) return;
  const double s = pose.depth;
  const double lo = std::max(s - scan_.pin_length(), 0.0);
  const double hi = std::min(s, scan_.hole_length());
  out->engaged_length = std::max(hi - lo, 0.0);
  out->engaged = out->engaged_length > 0.0;
  out->offset_distance = pose.offset.norm();
  out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
  if (!out->engaged) return;
  out->engaged_area = scan_.EngagedArea(s);
  const int last_step = steps() - 1;
  const double u = std::clamp(s / step(), 0.0, static_cast<double>(last_step));
  const int k = std::min(static_cast<int>(u), last_step - 1);
  const double t = u - k;
  Blend(k, k + 1, t, pose, scan_.Clearance(s), out);
}

}  // namespace fitfeel::conical
