#include "surfaces/conical/conical_contact_analyzer.h"

#include <algorithm>
#include <cmath>
#include <vector>

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
  step_ = settings.depth_step > 0.0 ? settings.depth_step
                                    : 0.5 * std::min(scan_.pin_pitch(), scan_.hole_pitch());
  if (!(range / step_ <= kMaxDepthSteps)) {
    throw UserError("conical contact table: a depth step of " + std::to_string(step_ * 1e3) +
                    " mm over " + std::to_string(range * 1e3) + " mm is more than " +
                    std::to_string(static_cast<int>(kMaxDepthSteps)) + " steps; take a coarser "
                    "model.depth_step");
  }
  last_step_ = std::max(1, static_cast<int>(std::ceil(range / step_ - 1e-9)));
  const int columns = scan_.columns();
  table_ = ColumnResponseTable(last_step_ + 1, columns, kSamples, scan_.texture());
  table_.FillAll([this](int k, int j, std::vector<ColumnCell>* cells) {
    scan_.ColumnCells(k * step_, j, cells);
  });
  direction_.resize(2, columns);
  for (int j = 0; j < columns; ++j) direction_.col(j) = scan_.direction(j);
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
  const double u = std::clamp(s / step_, 0.0, static_cast<double>(last_step_));
  const int k = std::min(static_cast<int>(u), last_step_ - 1);
  const double t = u - k;
  table_.Blend(k, k + 1, t, direction_, pose.offset, scan_.Clearance(s), out);
}

void ConicalContactAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                               Eigen::VectorXd* delta) const {
  scan_.InterferenceMap(pose, delta);
}

bool ConicalContactAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                             std::vector<Eigen::Vector2d>* polygon) const {
  return scan_.AssemblySpace(pose, polygon);
}

}  // namespace fitfeel::conical
