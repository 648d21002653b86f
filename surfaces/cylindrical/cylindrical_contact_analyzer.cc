#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/model/convex_polygon.h"
#include "framework/model/grid_rows.h"
#include "framework/model/section_contact.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/elastic_options.h"

namespace fitfeel::cylindrical {
namespace {

// An automatic step never makes more rows than this (a step of 3 um on a 60 mm stroke), however
// fine the grid: a haptic hand does not resolve the difference, and the tables stay in memory.
constexpr double kAutoDepthSteps = 20000;
// Half-width of the box that bounds an assembly space whose normals do not surround the origin;
// clearances are micrometres, so one metre never binds.
constexpr double kPolygonBound = 1.0;

Eigen::Vector2d Rotate(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

void CheckShape(const PartSpec& part, const SkinModelShape& sms) {
  const SurfaceGrid& g = sms.grid;
  if (g.columns < 3) {
    throw UserError("part '" + part.name + "': the assembly space needs at least 3 columns");
  }
  if (sms.variation.size() != g.size() || g.area.size() != g.size() ||
      g.column_angle.size() != g.columns) {
    throw UserError("part '" + part.name + "': skin model shape arrays do not match its grid");
  }
  if (!sms.variation.allFinite() || !(g.area.minCoeff() > 0.0)) {
    throw UserError("part '" + part.name + "': variations must be finite and cell areas positive");
  }
}

}  // namespace

void CylinderContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                        const PartSpec& outer, const SkinModelShape& outer_sms,
                                        const ModelSettings& settings) {
  if (inner.role != Role::kInner || outer.role != Role::kOuter) {
    throw UserError("cylindrical contact needs the inner part (shaft) first, the outer second");
  }
  CheckShape(inner, inner_sms);
  CheckShape(outer, outer_sms);
  const SurfaceGrid& gs = inner_sms.grid;
  const SurfaceGrid& gb = outer_sms.grid;
  if (gs.columns != gb.columns) {
    throw UserError("cylindrical contact needs the same number of columns on both parts (" +
                    MessageNumber(gs.columns) + " and " + MessageNumber(gb.columns) + ")");
  }
  n_ = gs.columns;
  angle_.assign(static_cast<std::size_t>(n_), 0.0);
  cos_ = sin_ = angle_;
  for (int j = 0; j < n_; ++j) {
    const double d = std::remainder(gs.column_angle[j] - gb.column_angle[j], 2 * std::numbers::pi);
    if (std::abs(d) > 1e-9) {
      throw UserError("cylindrical contact needs the same column angles on both parts");
    }
    angle_[static_cast<std::size_t>(j)] = gs.column_angle[j];
    cos_[static_cast<std::size_t>(j)] = std::cos(gs.column_angle[j]);
    sin_[static_cast<std::size_t>(j)] = std::sin(gs.column_angle[j]);
  }
  shaft_edges_ = RowEdges(inner, gs);
  bushing_edges_ = RowEdges(outer, gb);
  shaft_rows_ = gs.rows;
  bushing_rows_ = gb.rows;
  shaft_length_ = shaft_edges_.back();
  bushing_length_ = bushing_edges_.back();
  shaft_row_centre_ = gs.row_position.array() - (gs.row_position[0] - 0.5 * shaft_edges_[1]);
  if (shaft_rows_ == 1) shaft_row_centre_[0] = 0.5 * shaft_length_;
  v_shaft_ = inner_sms.variation;
  v_bushing_ = outer_sms.variation;
  shaft_area_ = gs.area;

  elastic_ = settings.law == "elastic";
  smoothing_ = settings.texture == TextureMode::kDin7190
                   ? Din7190RadialSmoothing(inner.texture, outer.texture)
                   : 0.0;
  std::optional<RigidSectionContact> solver;
  RigidFreedom freedom;
  double frame = 0.0;  // angle of the elastic solve's column 0
  if (elastic_) {
    for (int j = 0; j < n_; ++j) {
      if (std::abs(std::remainder(
              angle_[static_cast<std::size_t>(j)] - angle_[0] - 2.0 * std::numbers::pi * j / n_,
              2.0 * std::numbers::pi)) > 1e-9) {
        throw UserError("the elastic model needs equally spaced columns");
      }
    }
    const ElasticOptions options =
        settings.extra ? ParseElasticOptions(*settings.extra) : ElasticOptions{};
    block_ = 1;
    while (n_ / block_ > options.columns || n_ % block_ != 0 || (n_ / block_) % 2 != 0) {
      ++block_;
    }
    // Fewer than this and averaging loses the ovality-to-lobing range the model is about.
    if (n_ / block_ < ElasticOptions::kFewestColumns) block_ = 1;
    const PressFitDimensions d = PressFitDimensionsOf(inner, outer);
    PressFitSection section;
    section.d1 = d.d1;
    section.d2 = d.d2;
    section.di = d.di;
    section.shaft = inner.material;
    section.hub = outer.material;
    section.plane_strain = options.plane_strain;
    solver.emplace(section, n_ / block_);
    freedom.tilt = options.tilt;
    freedom.tilt_stiffness = options.tilt_stiffness;
    frame = angle_[0] + std::numbers::pi * (block_ - 1) / n_;
    section_ = section;
    freedom_ = freedom;
    frame_ = frame;
  }

  texture_ = settings.texture == TextureMode::kExpected
                 ? ExpectedInterferenceTable(EquivalentTexture(inner.texture, outer.texture))
                 : ExpectedInterferenceTable();

  // Auto step: the shortest row of either part. Between two row boundaries the slices only change
  // length, so every tabulated quantity is piecewise linear or smooth there; a finer step adds
  // nothing the cells can resolve.
  double min_row = std::numeric_limits<double>::infinity();
  for (const auto* e : {&shaft_edges_, &bushing_edges_}) {
    for (std::size_t i = 1; i < e->size(); ++i) min_row = std::min(min_row, (*e)[i] - (*e)[i - 1]);
  }
  if (settings.depth_step < 0.0) throw UserError("depth_step must not be negative");
  max_depth_ = shaft_length_ + bushing_length_;
  step_ = settings.depth_step > 0.0 ? settings.depth_step
                                    : std::max(min_row, max_depth_ / kAutoDepthSteps);
  const double steps = std::ceil(max_depth_ / step_);
  // Each step stores up to n + 4 polygon vertices.
  if (!(steps < kMaxDepthSteps) || !(steps * (n_ + 4) < kMaxDepthTableVertices)) {
    throw UserError("depth_step " + MessageNumber(step_) + " m gives " + MessageNumber(steps) +
                    " table rows of up to " + MessageNumber(n_ + 4) +
                    " vertices, more than the analyzer holds; use a coarser step");
  }
  const std::size_t count = static_cast<std::size_t>(steps) + 1;

  depth_.assign(count, 0.0);
  length_ = area_ = volume_ = max_delta_ = depth_;
  resultant_.assign(count, Eigen::Vector2d::Zero());
  anchor_ = resultant_;
  tilt_ = resultant_;
  normal_.assign(count, 0.0);
  empty_.assign(count, 0);
  unconstrained_.assign(count, 0);
  vertex_begin_.assign(count, 0);
  vertex_count_.assign(count, 0);
  vertices_.clear();
  centre_angles_.clear();
  origin_angles_.clear();
  centre_fan_.assign(count, 0);
  origin_fan_.assign(count, 0);
  max_vertices_ = 0;
  newton_iterations_ = 0;

  const std::size_t n = static_cast<std::size_t>(n_);
  std::vector<Slice> slices;
  std::vector<double> st, w, h(n), col_a(n), col_b(n), proj(n);
  std::vector<Eigen::Vector2d> polygon;
  Eigen::Vector2d warm(0.0, 0.0);
  Eigen::Vector4d elastic_warm = Eigen::Vector4d::Zero();  // in the elastic solve's frame
  std::vector<double> elastic_gap;
  std::vector<ContactSection> sections;
  // The contact set each bore row had at the last depth step that engaged it: one step deeper the
  // row meets the same or the next shaft row a fraction of a row further on, and its contact set
  // is mostly the same, so the section's LCP starts there instead of from the interference set.
  std::vector<std::vector<char>> row_contact(static_cast<std::size_t>(bushing_rows_));
  std::vector<std::size_t> row_contact_step(static_cast<std::size_t>(bushing_rows_), count);
  // And its factorizations: they depend only on the contact set, so the row's last ones are the
  // cheapest start for its next (updated by rows where the set changed a little).
  std::vector<CirculantContact::Factorization> row_factors(static_cast<std::size_t>(bushing_rows_));

  // Energy sum(w * max(0, p.u_j - st)^2) with its per-column first and second moments, one scan.
  auto energy = [&](const Eigen::Vector2d& p, bool moments) {
    double e = 0.0;
    if (moments) {
      std::fill(col_a.begin(), col_a.end(), 0.0);
      std::fill(col_b.begin(), col_b.end(), 0.0);
    }
    for (std::size_t j = 0; j < n; ++j) proj[j] = p.x() * cos_[j] + p.y() * sin_[j];
    const std::size_t rows = st.size() / n;
    for (std::size_t r = 0; r < rows; ++r) {
      const double* g = st.data() + r * n;
      const double* a = w.data() + r * n;
      for (std::size_t j = 0; j < n; ++j) {
        const double d = std::max(0.0, proj[j] - g[j]);
        e += a[j] * d * d;
        if (moments) {
          col_a[j] += a[j] * d;
          col_b[j] += d > 0.0 ? a[j] : 0.0;
        }
      }
    }
    return e;
  };

  for (std::size_t k = 0; k < count; ++k) {
    const double depth = static_cast<double>(k) * step_;
    depth_[k] = depth;
    vertex_begin_[k] = static_cast<int>(vertices_.size());
    SlicesAt(depth, &slices);
    if (slices.empty()) {
      unconstrained_[k] = 1;
      continue;
    }
    st.resize(slices.size() * n);
    w.resize(slices.size() * n);
    std::fill(h.begin(), h.end(), std::numeric_limits<double>::infinity());
    double length = 0.0, area = 0.0;
    for (std::size_t s = 0; s < slices.size(); ++s) {
      const Slice& sl = slices[s];
      const auto i = static_cast<std::size_t>(sl.shaft_row);
      const double share = sl.length / (shaft_edges_[i + 1] - shaft_edges_[i]);
      const Eigen::Index rs = static_cast<Eigen::Index>(sl.shaft_row) * n_;
      const Eigen::Index rb = static_cast<Eigen::Index>(sl.bushing_row) * n_;
      length += sl.length;
      for (std::size_t j = 0; j < n; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        const double gap = v_bushing_[rb + jj] - v_shaft_[rs + jj] + smoothing_;  // eq. 8
        st[s * n + j] = gap;
        w[s * n + j] = shaft_area_[rs + jj] * share;
        area += w[s * n + j];
        h[j] = std::min(h[j], gap);
      }
    }
    length_[k] = length;
    area_[k] = area;

    Eigen::Vector2d anchor;
    if (IntersectHalfPlanes(angle_, h, kPolygonBound, &polygon)) {
      vertices_.insert(vertices_.end(), polygon.begin(), polygon.end());
      vertex_count_[k] = static_cast<int>(polygon.size());
      max_vertices_ = std::max(max_vertices_, vertex_count_[k]);
      anchor = PolygonCentroid(polygon.data(), static_cast<int>(polygon.size()));
      centre_angles_.resize(vertices_.size(), 0.0);
      origin_angles_.resize(vertices_.size(), 0.0);
      centre_fan_[k] = FanAngles(polygon.data(), vertex_count_[k], anchor,
                                 centre_angles_.data() + vertex_begin_[k]);
      origin_fan_[k] = FanAngles(polygon.data(), vertex_count_[k], Eigen::Vector2d::Zero(),
                                 origin_angles_.data() + vertex_begin_[k]);
      warm = anchor;
    } else if (elastic_) {
      empty_[k] = 1;
      const std::size_t ne = n / static_cast<std::size_t>(block_);
      elastic_gap.assign(slices.size() * ne, 0.0);
      sections.assign(slices.size(), ContactSection{});
      const double lo = std::max(depth - shaft_length_, 0.0);
      double pos = lo, middle = lo + 0.5 * length;
      for (std::size_t sl = 0; sl < slices.size(); ++sl) {
        ContactSection& sec = sections[sl];
        sec.gap = elastic_gap.data() + sl * ne;
        sec.y = pos + 0.5 * slices[sl].length - middle;
        pos += slices[sl].length;
        for (std::size_t j = 0; j < n; ++j) {
          elastic_gap[sl * ne + j / static_cast<std::size_t>(block_)] += st[sl * n + j] / block_;
        }
        sec.cell_area = w[sl * n] * block_;  // equal cells along a slice
        const auto row = static_cast<std::size_t>(slices[sl].bushing_row);
        sec.warm_contact = row_contact_step[row] + 1 == k ? row_contact[row].data() : nullptr;
        sec.factorization = &row_factors[row];
      }
      const RigidContactResult r = solver->Solve(sections, freedom, elastic_warm);
      for (std::size_t sl = 0; sl < slices.size(); ++sl) {
        const auto row = static_cast<std::size_t>(slices[sl].bushing_row);
        row_contact[row] = solver->contact_sets()[sl];
        row_contact_step[row] = k;
      }
      elastic_warm << r.offset, r.tilt;
      anchor = Rotate(r.offset, frame);
      tilt_[k] = Rotate(r.tilt, frame);
      normal_[k] = r.normal_force;
      warm = anchor;
    } else {
      empty_[k] = 1;
      // Newton on the convex piecewise-quadratic energy, Armijo backtracking.
      Eigen::Vector2d p = warm;
      for (int it = 0; it < 100; ++it) {
        ++newton_iterations_;
        const double e0 = energy(p, true);
        Eigen::Vector2d grad(0.0, 0.0);
        Eigen::Matrix2d hess = Eigen::Matrix2d::Zero();
        for (std::size_t j = 0; j < n; ++j) {
          const Eigen::Vector2d u(cos_[j], sin_[j]);
          grad += 2.0 * col_a[j] * u;
          hess += 2.0 * col_b[j] * u * u.transpose();
        }
        const double trace = hess.trace();
        if (!(trace > 0.0)) break;  // no cell interferes: p is already a minimiser
        hess += 1e-12 * trace * Eigen::Matrix2d::Identity();
        const Eigen::Vector2d dir = -hess.ldlt().solve(grad);
        double alpha = 1.0;
        const double slope = grad.dot(dir);
        while (alpha > 1e-12 && energy(p + alpha * dir, false) > e0 + 1e-4 * alpha * slope) {
          alpha *= 0.5;
        }
        p += alpha * dir;
        // A picometre-scale step on micrometre interferences: converged.
        if ((alpha * dir).norm() < 1e-13) break;
      }
      anchor = p;
      warm = p;
    }
    anchor_[k] = anchor;

    // Interference at the anchor: none is possible with a sharp contact inside the polygon.
    if (empty_[k] || !texture_.sharp()) {
      double volume = 0.0, max_delta = 0.0;
      Eigen::Vector2d resultant(0.0, 0.0);
      for (std::size_t j = 0; j < n; ++j) proj[j] = anchor.x() * cos_[j] + anchor.y() * sin_[j];
      std::fill(col_a.begin(), col_a.end(), 0.0);
      for (std::size_t c = 0; c < st.size(); ++c) {
        const std::size_t j = c - (c / n) * n;
        const double d = texture_(st[c] - proj[j]);
        col_a[j] += w[c] * d;
        max_delta = std::max(max_delta, d);
      }
      for (std::size_t j = 0; j < n; ++j) {
        volume += col_a[j];
        resultant += col_a[j] * Eigen::Vector2d(cos_[j], sin_[j]);
      }
      volume_[k] = volume;
      max_delta_[k] = max_delta;
      resultant_[k] = resultant;
    }
  }
}

void CylinderContactAnalyzer::SlicesAt(double depth, std::vector<Slice>* slices) const {
  slices->clear();
  const double shift = depth - shaft_length_;  // bushing coordinate of the shaft's trailing end
  const double lo = std::max(shift, 0.0);
  const double hi = std::min(depth, bushing_length_);
  if (!(hi > lo)) return;
  // First rows containing lo.
  int i = static_cast<int>(std::upper_bound(shaft_edges_.begin(), shaft_edges_.end(), lo - shift) -
                           shaft_edges_.begin()) -
          1;
  int k = static_cast<int>(std::upper_bound(bushing_edges_.begin(), bushing_edges_.end(), lo) -
                           bushing_edges_.begin()) -
          1;
  i = std::clamp(i, 0, shaft_rows_ - 1);
  k = std::clamp(k, 0, bushing_rows_ - 1);
  // Slivers below a femtometre are rounding of equal boundaries, not geometry.
  constexpr double kSliver = 1e-15;
  double pos = lo;
  while (pos < hi - kSliver && i < shaft_rows_ && k < bushing_rows_) {
    const double shaft_end = shaft_edges_[static_cast<std::size_t>(i) + 1] + shift;
    const double bushing_end = bushing_edges_[static_cast<std::size_t>(k) + 1];
    const double next = std::min({shaft_end, bushing_end, hi});
    if (next - pos > kSliver) slices->push_back({i, k, next - pos});
    if (shaft_end <= next + kSliver) ++i;
    if (bushing_end <= next + kSliver) ++k;
    pos = next;
  }
}

bool CylinderContactAnalyzer::Locate(double depth, std::size_t* k, double* t) const noexcept {
  if (!(depth > 0.0) || !(depth < max_depth_)) return false;
  const double s = depth / step_;
  const std::size_t last = depth_.size() - 1;
  std::size_t i = static_cast<std::size_t>(s);
  if (i >= last) i = last - 1;
  *k = i;
  *t = std::clamp(s - static_cast<double>(i), 0.0, 1.0);
  return true;
}

Eigen::Vector2d CylinderContactAnalyzer::AnchorAt(std::size_t k,
                                                  const Eigen::Vector2d& x) const noexcept {
  if (unconstrained_[k]) return x;
  if (empty_[k]) return anchor_[k];
  PolygonFan fan;
  if (centre_fan_[k]) fan = {anchor_[k], centre_angles_.data() + vertex_begin_[k]};
  return ProjectOntoPolygon(vertices_.data() + vertex_begin_[k], vertex_count_[k], fan, x);
}

void CylinderContactAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  const Eigen::Vector2d x = pose.offset;
  out->offset_distance = x.norm();
  out->offset_angle = std::atan2(x.y(), x.x());
  std::size_t k = 0;
  double t = 0.0;
  // A non-finite offset is an upstream fault: report no contact rather than NaN forces.
  if (!x.allFinite() || !Locate(pose.depth, &k, &t)) return;
  const double s = 1.0 - t;
  out->engaged_length = s * length_[k] + t * length_[k + 1];
  out->engaged_area = s * area_[k] + t * area_[k + 1];
  out->engaged = out->engaged_length > 0.0;
  if (!out->engaged) return;

  const Eigen::Vector2d anchor = s * AnchorAt(k, x) + t * AnchorAt(k + 1, x);
  const Eigen::Vector2d pen = x - anchor;
  out->penetration = pen.norm();
  if (out->penetration > 0.0) out->penetration_direction = pen / out->penetration;

  const std::size_t nearest = t < 0.5 ? k : k + 1;
  out->interference = empty_[nearest] != 0;
  if (!out->interference && !unconstrained_[nearest]) {
    const Eigen::Vector2d dir(std::cos(out->offset_angle), std::sin(out->offset_angle));
    PolygonFan fan;
    if (origin_fan_[nearest]) {
      fan = {Eigen::Vector2d::Zero(), origin_angles_.data() + vertex_begin_[nearest]};
    }
    out->assembly_extent =
        RayExtent(vertices_.data() + vertex_begin_[nearest], vertex_count_[nearest], fan, dir);
  }
  out->interference_volume = s * volume_[k] + t * volume_[k + 1];
  out->max_interference = s * max_delta_[k] + t * max_delta_[k + 1];
  out->pressure_resultant = s * resultant_[k] + t * resultant_[k + 1];
  out->normal_force = s * normal_[k] + t * normal_[k + 1];
  out->tilt = s * tilt_[k] + t * tilt_[k + 1];
}

void CylinderContactAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                                Eigen::VectorXd* delta) const {
  delta->setZero(static_cast<Eigen::Index>(shaft_rows_) * n_);
  std::size_t k = 0;
  double t = 0.0;
  if (!pose.offset.allFinite()) throw UserError("interference map of a non-finite axis offset");
  if (!Locate(pose.depth, &k, &t)) return;
  // Where the laws take the axis to be: under interference the energy-minimising position (the
  // offset from it is the radial spring's), in clearance the pose's own offset, so that a shaft
  // pressed against the bore by a radial load shows its contact line.
  const bool interference = empty_[t < 0.5 ? k : k + 1] != 0;
  const Eigen::Vector2d anchor =
      interference
          ? Eigen::Vector2d((1.0 - t) * AnchorAt(k, pose.offset) + t * AnchorAt(k + 1, pose.offset))
          : pose.offset;
  const double shift = pose.depth - shaft_length_;
  for (int i = 0; i < shaft_rows_; ++i) {
    const double pos = shaft_row_centre_[i] + shift;  // bushing coordinate of the row's centre
    if (pos < 0.0 || pos >= bushing_length_) continue;
    int b = static_cast<int>(std::upper_bound(bushing_edges_.begin(), bushing_edges_.end(), pos) -
                             bushing_edges_.begin()) -
            1;
    b = std::clamp(b, 0, bushing_rows_ - 1);
    for (int j = 0; j < n_; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      const double gap = v_bushing_[b * n_ + j] - v_shaft_[i * n_ + j] + smoothing_ -
                         (anchor.x() * cos_[jj] + anchor.y() * sin_[jj]);
      (*delta)[i * n_ + j] = texture_(gap);
    }
  }
}

bool CylinderContactAnalyzer::PressureMap(const MatingPose& pose, Eigen::VectorXd* pressure) const {
  if (!elastic_ || pressure == nullptr) return false;
  if (!pose.offset.allFinite()) throw UserError("pressure map of a non-finite axis offset");
  pressure->setZero(static_cast<Eigen::Index>(shaft_rows_) * n_);
  std::size_t k = 0;
  double t = 0.0;
  if (!Locate(pose.depth, &k, &t)) return true;
  const std::size_t n = static_cast<std::size_t>(n_), ne = n / static_cast<std::size_t>(block_);
  const double shift = pose.depth - shaft_length_;
  const double lo = std::max(shift, 0.0), hi = std::min(pose.depth, bushing_length_);
  std::vector<int> rows;
  std::vector<double> gaps;
  for (int i = 0; i < shaft_rows_; ++i) {
    const double pos = shaft_row_centre_[i] + shift;
    if (pos < 0.0 || pos >= bushing_length_) continue;
    int b = static_cast<int>(std::upper_bound(bushing_edges_.begin(), bushing_edges_.end(), pos) -
                             bushing_edges_.begin()) -
            1;
    b = std::clamp(b, 0, bushing_rows_ - 1);
    rows.push_back(i);
    gaps.resize(rows.size() * ne, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      const double gap = v_bushing_[b * n_ + static_cast<Eigen::Index>(j)] -
                         v_shaft_[i * n_ + static_cast<Eigen::Index>(j)] + smoothing_;
      gaps[(rows.size() - 1) * ne + j / static_cast<std::size_t>(block_)] += gap / block_;
    }
  }
  if (rows.empty()) return true;
  std::vector<ContactSection> sections(rows.size());
  for (std::size_t s = 0; s < rows.size(); ++s) {
    sections[s].gap = gaps.data() + s * ne;
    sections[s].cell_area = shaft_area_[rows[s] * n_] * block_;
    sections[s].y = shaft_row_centre_[rows[s]] + shift - 0.5 * (lo + hi);
  }
  const std::size_t nearest = t < 0.5 ? k : k + 1;
  Eigen::Vector4d warm;
  warm << Rotate(anchor_[nearest], -frame_), Rotate(tilt_[nearest], -frame_);
  RigidSectionContact solver(section_, static_cast<int>(ne));
  solver.Solve(sections, freedom_, warm);
  for (std::size_t s = 0; s < rows.size(); ++s) {
    for (std::size_t j = 0; j < n; ++j) {
      (*pressure)[rows[s] * n_ + static_cast<Eigen::Index>(j)] =
          solver.pressures()[s * ne + j / static_cast<std::size_t>(block_)];
    }
  }
  return true;
}

// The tabulated polygon of the nearer depth step: what the tick interpolates between.
bool CylinderContactAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                              std::vector<Eigen::Vector2d>* polygon) const {
  std::size_t k = 0;
  double t = 0.0;
  if (!Locate(pose.depth, &k, &t)) return true;
  if (t >= 0.5) ++k;
  if (unconstrained_[k] || empty_[k]) return true;
  const auto begin = vertices_.begin() + vertex_begin_[k];
  polygon->assign(begin, begin + vertex_count_[k]);
  return true;
}

}  // namespace fitfeel::cylindrical
