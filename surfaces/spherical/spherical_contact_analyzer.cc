#include "surfaces/spherical/spherical_contact_analyzer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fitfeel::spherical {

void SphericalContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                         const PartSpec& outer, const SkinModelShape& outer_sms,
                                         const ModelSettings& settings) {
  scan_.Prepare(inner, inner_sms, outer, outer_sms, settings);
  const int columns = scan_.columns();
  steps_ = columns * kStepsPerColumn;
  step_ = 2.0 * M_PI / steps_;
  table_ = ColumnResponseTable(steps_, columns, kSamples, scan_.texture());
  table_.FillAll([this](int q, int j, std::vector<ColumnCell>* cells) {
    scan_.ColumnCells(q * step_, j, cells);
  });
  direction_.resize(2, columns);
  for (int j = 0; j < columns; ++j) direction_.col(j) = scan_.direction(j);
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
  double u = std::fmod(pose.angle / step_, static_cast<double>(steps_));
  if (u < 0.0) u += steps_;
  const int q = std::min(static_cast<int>(u), steps_ - 1);
  const double t = u - q;
  const int q1 = q + 1 == steps_ ? 0 : q + 1;
  table_.Blend(q, q1, t, direction_, pose.offset, 0.0, out);
}

void SphericalContactAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                                 Eigen::VectorXd* delta) const {
  scan_.InterferenceMap(pose, delta);
}

bool SphericalContactAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                               std::vector<Eigen::Vector2d>* polygon) const {
  return scan_.AssemblySpace(pose, polygon);
}

}  // namespace fitfeel::spherical
