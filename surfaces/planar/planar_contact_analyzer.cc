#include "surfaces/planar/planar_contact_analyzer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "surfaces/common/grid_rows.h"
#include "surfaces/planar/planar_geometry.h"

namespace fitfeel::planar {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void CheckShape(const PartSpec& part, const SkinModelShape& sms) {
  const SurfaceGrid& g = sms.grid;
  if (sms.variation.size() != g.size() || g.area.size() != g.size() ||
      g.centre.cols() != g.size()) {
    throw UserError("part '" + part.name + "': skin model shape arrays do not match its grid");
  }
  if (!sms.variation.allFinite() || !(g.area.minCoeff() > 0.0)) {
    throw UserError("part '" + part.name + "': variations must be finite and cell areas positive");
  }
}

}  // namespace

void PlanarContactAnalyzer::SlicesAt(double depth, std::vector<Slice>* slices) const {
  slices->clear();
  // Inner row i spans [a_i, a_i+1] from the inner trailing end; in outer coordinates it sits at
  // a + depth - inner_length.
  const double shift = depth - inner_length_;
  for (std::size_t i = 0; i + 1 < inner_edges_.size(); ++i) {
    const double lo = inner_edges_[i] + shift, hi = inner_edges_[i + 1] + shift;
    if (hi <= 0.0 || lo >= outer_length_) continue;
    for (std::size_t r = 0; r + 1 < outer_edges_.size(); ++r) {
      const double overlap = std::min(hi, outer_edges_[r + 1]) - std::max(lo, outer_edges_[r]);
      // A sliver left by rounding where row boundaries coincide is no engagement: it would put
      // a row that does not face this one into the minima.
      if (overlap > min_overlap_) {
        slices->push_back({static_cast<int>(i), static_cast<int>(r), overlap});
      }
    }
  }
}

void PlanarContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                      const PartSpec& outer, const SkinModelShape& outer_sms,
                                      const ModelSettings& settings) {
  if (inner.role != Role::kInner || outer.role != Role::kOuter) {
    throw UserError("planar contact needs the inner part (key, shaft) first, the outer second");
  }
  CheckShape(inner, inner_sms);
  CheckShape(outer, outer_sms);
  texture_ = ContactTexture(inner.texture, outer.texture, settings.texture);
  const auto* geometry = dynamic_cast<const PlanarGeometry*>(inner.geometry.get());
  half_height_ = geometry != nullptr ? 0.5 * geometry->height() : 0.0;
  layout_ = LayoutOf(inner_sms.grid);
  const FaceLayout outer_layout = LayoutOf(outer_sms.grid);
  if (outer_layout.faces != layout_.faces ||
      outer_layout.columns_per_face != layout_.columns_per_face) {
    throw UserError("planar contact needs the same faces and strips on both parts (" +
                    std::to_string(inner_sms.grid.columns) + " and " +
                    std::to_string(outer_sms.grid.columns) + " columns)");
  }
  axes_ = layout_.faces / 2;
  inner_edges_ = RowEdges(inner, inner_sms.grid);
  outer_edges_ = RowEdges(outer, outer_sms.grid);
  inner_length_ = inner_edges_.back();
  outer_length_ = outer_edges_.back();
  v_inner_ = inner_sms.variation;
  v_outer_ = outer_sms.variation;
  inner_area_ = inner_sms.grid.area;

  double min_row = kInf;
  for (const auto* e : {&inner_edges_, &outer_edges_}) {
    for (std::size_t i = 1; i < e->size(); ++i) min_row = std::min(min_row, (*e)[i] - (*e)[i - 1]);
  }
  if (settings.depth_step < 0.0) throw UserError("depth_step must not be negative");
  min_overlap_ = 1e-9 * min_row;
  // Auto: the shortest row of either part; between row boundaries every tabulated quantity is
  // linear in depth or constant, so a finer step resolves nothing more.
  step_ = settings.depth_step > 0.0 ? settings.depth_step : min_row;
  max_depth_ = inner_length_ + outer_length_;
  const double steps = std::ceil(max_depth_ / step_);
  if (!(steps < kMaxDepthSteps)) {
    throw UserError("depth_step gives more than 2e6 table rows; use a coarser step");
  }
  const std::size_t count = static_cast<std::size_t>(steps) + 1;
  depth_.assign(count, 0.0);
  length_ = area_ = volume_ = max_delta_ = depth_;
  resultant_.assign(count, Eigen::Vector2d::Zero());
  engaged_.assign(count, 0);
  lower_.assign(2 * count, -kInf);
  upper_.assign(2 * count, kInf);
  balance_.assign(2 * count, 0.0);
  empty_.assign(2 * count, 0);

  const int n = inner_sms.grid.columns;
  std::vector<Slice> slices;
  std::vector<double> gap, weight;
  for (std::size_t k = 0; k < count; ++k) {
    const double depth = static_cast<double>(k) * step_;
    depth_[k] = depth;
    SlicesAt(depth, &slices);
    if (slices.empty()) continue;
    engaged_[k] = 1;
    gap.resize(slices.size() * static_cast<std::size_t>(n));
    weight.resize(gap.size());
    double length = 0.0, area = 0.0;
    for (std::size_t s = 0; s < slices.size(); ++s) {
      const Slice& sl = slices[s];
      const auto i = static_cast<std::size_t>(sl.inner_row);
      const double share = sl.length / (inner_edges_[i + 1] - inner_edges_[i]);
      length += sl.length;
      for (int j = 0; j < n; ++j) {
        const Eigen::Index ci = static_cast<Eigen::Index>(sl.inner_row) * n + j;
        const Eigen::Index co = static_cast<Eigen::Index>(sl.outer_row) * n + j;
        const std::size_t c = s * static_cast<std::size_t>(n) + static_cast<std::size_t>(j);
        gap[c] = v_outer_[co] - v_inner_[ci];  // eq. 8
        weight[c] = inner_area_[ci] * share;
        area += weight[c];
      }
    }
    // Each slice covers all strips of one inner row: the engaged length counts every slice once.
    length_[k] = length;
    area_[k] = area;

    double volume = 0.0, max_delta = 0.0;
    Eigen::Vector2d resultant(0.0, 0.0);
    for (int axis = 0; axis < axes_; ++axis) {
      const int plus = 2 * axis, minus = 2 * axis + 1;
      double hi = kInf, lo = -kInf;
      for (std::size_t c = 0; c < gap.size(); ++c) {
        const int face = layout_.face_of(static_cast<int>(c % static_cast<std::size_t>(n)));
        if (face == plus) hi = std::min(hi, gap[c]);
        if (face == minus) lo = std::max(lo, -gap[c]);
      }
      const std::size_t a = Index(static_cast<int>(k), axis);
      lower_[a] = lo;
      upper_[a] = hi;
      // Where the axis sits for the interference sums: the middle of the interval in clearance
      // (the texture's expected interference is then the least the faces can have, shared evenly
      // by the two faces, as the cylindrical analyzer takes the polygon's centroid), or the
      // balance position.
      double x = 0.5 * (lo + hi);
      if (lo > hi) {
        empty_[a] = 1;
        // Balance of the two faces' Winkler forces: f(x) = sum_+ w (x - S)+ - sum_- w (-x - S)+
        // is nondecreasing, <= 0 at x = hi and >= 0 at x = lo.
        auto force = [&](double p) {
          double f = 0.0;
          for (std::size_t c = 0; c < gap.size(); ++c) {
            const int face = layout_.face_of(static_cast<int>(c % static_cast<std::size_t>(n)));
            if (face == plus) f += weight[c] * std::max(0.0, p - gap[c]);
            if (face == minus) f -= weight[c] * std::max(0.0, -p - gap[c]);
          }
          return f;
        };
        double left = hi, right = lo;
        for (int it = 0;
             it < 200 && right - left > 1e-15 * (std::abs(left) + std::abs(right)) + 1e-18; ++it) {
          const double mid = 0.5 * (left + right);
          (force(mid) < 0.0 ? left : right) = mid;
        }
        x = 0.5 * (left + right);
      }
      balance_[a] = x;
      // Interference at that position: the sharp max(0, -gap) or, with expected texture, the
      // expected interference of the equivalent rough-on-smooth contact. None is possible with a
      // sharp contact inside the interval.
      if (!empty_[a] && texture_.sharp()) continue;
      const Eigen::Vector2d u_plus =
          axis == 0 ? Eigen::Vector2d(1.0, 0.0) : Eigen::Vector2d(0.0, 1.0);
      for (std::size_t c = 0; c < gap.size(); ++c) {
        const int face = layout_.face_of(static_cast<int>(c % static_cast<std::size_t>(n)));
        if (face != plus && face != minus) continue;
        const double along = face == plus ? x : -x;
        const double delta = texture_(gap[c] - along);
        if (delta <= 0.0) continue;
        volume += weight[c] * delta;
        max_delta = std::max(max_delta, delta);
        resultant += (face == plus ? 1.0 : -1.0) * weight[c] * delta * u_plus;
      }
    }
    volume_[k] = volume;
    max_delta_[k] = max_delta;
    resultant_[k] = resultant;
  }
}

bool PlanarContactAnalyzer::Locate(double depth, std::size_t* k, double* t) const noexcept {
  const std::size_t last = depth_.size() - 1;
  if (!(depth > 0.0)) {
    *k = 0;
    *t = 0.0;
    return depth == 0.0;
  }
  if (depth >= depth_[last]) {
    *k = last;
    *t = 0.0;
    return true;
  }
  const double s = depth / step_;
  *k = std::min(static_cast<std::size_t>(s), last - 1);
  *t = std::clamp(s - static_cast<double>(*k), 0.0, 1.0);
  return true;
}

double PlanarContactAnalyzer::AnchorAt(std::size_t k, int axis, double x,
                                       double twist_reach) const noexcept {
  if (!engaged_[k] || axis >= axes_) return x;
  const std::size_t a = Index(static_cast<int>(k), axis);
  if (empty_[a]) return balance_[a];
  const double low = lower_[a] + twist_reach, high = upper_[a] - twist_reach;
  // Twisted beyond the play: both faces' edges press, the part held between them.
  if (low > high) return 0.5 * (lower_[a] + upper_[a]);
  return std::clamp(x, low, high);
}

void PlanarContactAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  std::size_t k = 0;
  double t = 0.0;
  Locate(pose.depth, &k, &t);
  if (!std::isfinite(pose.depth) || !pose.offset.allFinite()) return;
  const std::size_t k1 = std::min(k + 1, depth_.size() - 1);
  const double w0 = 1.0 - t, w1 = t;
  auto blend = [&](const std::vector<double>& v) { return w0 * v[k] + w1 * v[k1]; };
  out->engaged = (w0 > 0.0 && engaged_[k]) || (w1 > 0.0 && engaged_[k1]);
  out->engaged_length = blend(length_);
  out->engaged_area = blend(area_);
  out->interference_volume = blend(volume_);
  out->max_interference = blend(max_delta_);
  out->pressure_resultant = w0 * resultant_[k] + w1 * resultant_[k1];
  bool interference = false;
  for (int axis = 0; axis < axes_; ++axis) {
    const std::size_t nearest = t < 0.5 ? k : k1;
    interference =
        interference || (engaged_[nearest] && empty_[Index(static_cast<int>(nearest), axis)]);
  }
  out->interference = interference;
  const double reach = std::isfinite(pose.angle) ? half_height_ * std::abs(pose.angle) : 0.0;
  Eigen::Vector2d anchor;
  for (int axis = 0; axis < 2; ++axis) {
    const double x = pose.offset[axis];
    anchor[axis] = w0 * AnchorAt(k, axis, x, reach) + w1 * AnchorAt(k1, axis, x, reach);
  }
  const Eigen::Vector2d away = pose.offset - anchor;
  out->offset_distance = pose.offset.norm();
  out->penetration = away.norm();
  if (out->penetration > 0.0) out->penetration_direction = away / out->penetration;
  out->offset_angle = out->penetration > 0.0 ? std::atan2(away.y(), away.x())
                                             : std::atan2(pose.offset.y(), pose.offset.x());
  out->assembly_extent = std::max(0.0, out->offset_distance - out->penetration);
}

void PlanarContactAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                              Eigen::VectorXd* delta) const {
  *delta = Eigen::VectorXd::Zero(v_inner_.size());
  std::size_t k = 0;
  double t = 0.0;
  Locate(pose.depth, &k, &t);
  const std::size_t k1 = std::min(k + 1, depth_.size() - 1);
  Eigen::Vector2d anchor;
  for (int axis = 0; axis < 2; ++axis) {
    const double x = pose.offset[axis];
    anchor[axis] = (1.0 - t) * AnchorAt(k, axis, x, 0.0) + t * AnchorAt(k1, axis, x, 0.0);
  }
  const int n =
      static_cast<int>(v_inner_.size() / (static_cast<Eigen::Index>(inner_edges_.size()) - 1));
  const double shift = pose.depth - inner_length_;
  for (std::size_t i = 0; i + 1 < inner_edges_.size(); ++i) {
    // The outer row facing the inner row's centre.
    const double y = 0.5 * (inner_edges_[i] + inner_edges_[i + 1]) + shift;
    if (y < 0.0 || y >= outer_length_) continue;
    const auto r = static_cast<std::size_t>(
        std::upper_bound(outer_edges_.begin(), outer_edges_.end(), y) - outer_edges_.begin() - 1);
    for (int j = 0; j < n; ++j) {
      const int face = layout_.face_of(j);
      const int axis = face / 2;
      const double along = (face % 2 == 0 ? 1.0 : -1.0) * anchor[axis];
      const Eigen::Index ci = static_cast<Eigen::Index>(i) * n + j;
      const Eigen::Index co = static_cast<Eigen::Index>(r) * n + j;
      (*delta)[ci] = texture_(v_outer_[co] - v_inner_[ci] - along);
    }
  }
}

bool PlanarContactAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                           std::vector<Eigen::Vector2d>* polygon) const {
  polygon->clear();
  std::size_t k = 0;
  double t = 0.0;
  if (!std::isfinite(pose.depth) || !Locate(pose.depth, &k, &t)) return true;
  if (t >= 0.5) k = std::min(k + 1, depth_.size() - 1);
  if (!engaged_[k]) return true;
  double lo[2] = {0.0, 0.0}, hi[2] = {0.0, 0.0};
  for (int axis = 0; axis < axes_; ++axis) {
    const std::size_t a = Index(static_cast<int>(k), axis);
    if (empty_[a]) return true;
    lo[axis] = lower_[a];
    hi[axis] = upper_[a];
  }
  for (int axis = axes_; axis < 2; ++axis) {
    const double half = 0.5 * (hi[0] - lo[0]);
    lo[axis] = -half;
    hi[axis] = half;
  }
  *polygon = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  return true;
}

}  // namespace fitfeel::planar
