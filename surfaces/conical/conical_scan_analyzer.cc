#include "surfaces/conical/conical_scan_analyzer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/model/convex_polygon.h"
#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {

void ConicalScanAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                       const PartSpec& outer, const SkinModelShape& outer_sms,
                                       const ModelSettings& settings) {
  texture_ = ContactTexture(inner.texture, outer.texture, settings.texture);
  const ConicalGeometry& pin = GeometryOf(inner);
  const ConicalGeometry& hole = GeometryOf(outer);
  const SurfaceGrid& pg = inner_sms.grid;
  const SurfaceGrid& hg = outer_sms.grid;
  revolution::CheckSharedColumns(pg, hg, "taper pin and hole");
  pin_rows_ = pg.rows;
  hole_rows_ = hg.rows;
  columns_ = pg.columns;
  pin_length_ = pin.length();
  hole_length_ = hole.length();
  pin_pitch_ = pin_length_ / pin_rows_;
  hole_pitch_ = hole_length_ / hole_rows_;
  tan_alpha_ = 0.5 * hole.taper();
  taper_ = hole.taper();
  hole_small_diameter_ = hole.small_diameter();
  area_factor_ = M_PI / std::cos(hole.half_angle()) / columns_;
  pin_row_ = pg.row_position;
  tiled_ = pin_row_.size() == pin_rows_;
  for (int i = 0; i < pin_rows_ && tiled_; ++i) {
    tiled_ = std::abs(pin_row_(i) - (i + 0.5) * pin_pitch_) <= 1e-12 * pin_length_;
  }
  pin_v_.resize(pin_rows_, columns_);
  hole_v_.resize(hole_rows_, columns_);
  for (int i = 0; i < pin_rows_; ++i) {
    for (int j = 0; j < columns_; ++j) pin_v_(i, j) = inner_sms.variation(pg.index(i, j));
  }
  for (int i = 0; i < hole_rows_; ++i) {
    for (int j = 0; j < columns_; ++j) hole_v_(i, j) = outer_sms.variation(hg.index(i, j));
  }
  direction_.resize(2, columns_);
  for (int j = 0; j < columns_; ++j) {
    direction_.col(j) << std::cos(pg.column_angle(j)), std::sin(pg.column_angle(j));
  }
}

template <class Visit>
void ConicalScanAnalyzer::ForEachRow(double s, Visit&& visit) const noexcept {
  for (int i = 0; i < pin_rows_; ++i) {
    const double y = s - pin_row_(i);
    const double lo = std::max(y - 0.5 * pin_pitch_, 0.0);
    const double hi = std::min(y + 0.5 * pin_pitch_, hole_length_);
    if (!(hi > lo)) continue;
    const double area = SlantArea(lo, hi);
    // Linear interpolation between hole row centres, constant beyond the end rows.
    const double u = std::clamp(y / hole_pitch_ - 0.5, 0.0, hole_rows_ - 1.0);
    const int k = std::min(static_cast<int>(u), std::max(hole_rows_ - 2, 0));
    const double f = hole_rows_ > 1 ? u - k : 0.0;
    const int k1 = std::min(k + 1, hole_rows_ - 1);
    visit(i, area, k, k1, f);
  }
}

template <class Visit>
void ConicalScanAnalyzer::ForEachCell(const MatingPose& pose, Visit&& visit) const noexcept {
  const double clearance = Clearance(pose.depth);
  ForEachRow(pose.depth, [&](int i, double area, int k, int k1, double f) {
    for (int j = 0; j < columns_; ++j) {
      const double hole_v = (1.0 - f) * hole_v_(k, j) + f * hole_v_(k1, j);
      const double gap = clearance + hole_v - pin_v_(i, j) - pose.offset.dot(direction_.col(j));
      visit(j, area, texture_(gap), i);
    }
  });
}

double ConicalScanAnalyzer::EngagedArea(double depth) const noexcept {
  if (tiled_) {
    // Rows that tile the pin cover [depth - pin length, depth] of the hole between them: the
    // slant area over that span in closed form, the sum of the rows' own (per tick: O(1), not a
    // pass over the rows).
    const double a = std::clamp(depth - pin_length_, 0.0, hole_length_);
    const double b = std::clamp(depth, 0.0, hole_length_);
    return b > a ? SlantArea(a, b) * columns_ : 0.0;
  }
  double area = 0.0;
  ForEachRow(depth, [&](int, double a, int, int, double) { area += a; });
  return area * columns_;
}

void ConicalScanAnalyzer::ColumnCells(double depth, int j, std::vector<ColumnCell>* cells) const {
  cells->clear();
  ForEachRow(depth, [&](int i, double area, int k, int k1, double f) {
    const double hole_v = (1.0 - f) * hole_v_(k, j) + f * hole_v_(k1, j);
    cells->push_back({area, 1.0, hole_v - pin_v_(i, j)});
  });
}

void ConicalScanAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  // A non-finite pose (a device glitch) is no contact rather than NaN forces.
  if (!std::isfinite(pose.depth) || !pose.offset.allFinite()) return;
  const double lo = std::max(pose.depth - pin_length_, 0.0);
  const double hi = std::min(pose.depth, hole_length_);
  out->engaged_length = std::max(hi - lo, 0.0);
  out->engaged = out->engaged_length > 0.0;
  out->offset_distance = pose.offset.norm();
  out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
  if (!out->engaged) return;
  ForEachCell(pose, [&](int j, double area, double delta, int) {
    out->engaged_area += area;
    if (delta > 0.0) {
      out->interference_volume += delta * area;
      out->max_interference = std::max(out->max_interference, delta);
      out->pressure_resultant += delta * area * direction_.col(j);
    }
  });
  out->interference = out->interference_volume > 0.0;
}

void ConicalScanAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                               Eigen::VectorXd* delta) const {
  delta->setZero(pin_rows_ * columns_);
  ForEachCell(pose, [&](int j, double, double d, int i) { (*delta)(i * columns_ + j) = d; });
}

bool ConicalScanAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                          std::vector<Eigen::Vector2d>* polygon) const {
  polygon->clear();
  if (!std::isfinite(pose.depth)) return true;
  std::vector<double> h(columns_, std::numeric_limits<double>::infinity());
  bool engaged = false;
  ForEachRow(pose.depth, [&](int i, double, int k, int k1, double f) {
    engaged = true;
    for (int j = 0; j < columns_; ++j) {
      const double hole_v = (1.0 - f) * hole_v_(k, j) + f * hole_v_(k1, j);
      h[j] = std::min(h[j], hole_v - pin_v_(i, j));
    }
  });
  if (!engaged) return true;
  std::vector<double> angle(columns_);
  for (int j = 0; j < columns_; ++j) {
    angle[j] = std::atan2(direction_(1, j), direction_(0, j));
    h[j] += Clearance(pose.depth);
  }
  // Columns all round the axis close the polygon; the bound only guards degenerate grids.
  if (!IntersectHalfPlanes(angle, h, hole_small_diameter_, polygon)) polygon->clear();
  return true;
}

}  // namespace fitfeel::conical
