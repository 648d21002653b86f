#include "surfaces/thread/thread_contact_analyzer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "framework/core/error.h"
#include "framework/model/convex_polygon.h"
#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/fastener_tables.h"
#include "surfaces/thread/joint_model.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_options.h"
#include "surfaces/thread/turn_load_distribution.h"

namespace fitfeel::thread {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A bolt turned by `angle` about +y: its frame's vectors in the nut's.
Eigen::Vector3d Turn(const Eigen::Vector3d& v, double c, double s) {
  return {c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z()};
}

}  // namespace

// The screw phase of a pose (ThreadContactAnalyzer): taken to the nearest turn and folded at a
// quarter pitch, the whole turns it dropped (rad, for the nut's helix) and the offset in the
// bolt's turned frame.
struct ScrewPhase {
  double folded = 0.0, shift = 0.0, cos = 1.0, sin = 0.0;
  // The deviations' weight: 1 up to the fold, falling to 0 where the crests meet, so that the
  // nut's turn changing there (shift) moves nothing.
  double deviations = 1.0;
  // In the bolt's frame: the displacement of its leading end from the screw's place (the folded
  // phase along y, the offset across) with what a tilt about the nut's entrance adds there, and
  // the tilt's rotation vector: a cell at p moves by move + spin x p, first order in the tilt.
  Eigen::Vector3d move{0.0, 0.0, 0.0}, spin{0.0, 0.0, 0.0};
};

namespace {

ScrewPhase PhaseOf(const MatingPose& pose, double pitch) {
  ScrewPhase screw;
  const double phase = pose.depth - pitch / kTwoPi * pose.angle;
  const double turns = std::round(phase / pitch);
  screw.folded = phase - turns * pitch;
  if (std::abs(screw.folded) > 0.25 * pitch) {
    screw.folded = std::copysign(0.5 * pitch - std::abs(screw.folded), screw.folded);
    screw.deviations = std::abs(screw.folded) / (0.25 * pitch);
  }
  screw.shift = turns * kTwoPi;
  screw.cos = std::cos(pose.angle);
  screw.sin = std::sin(pose.angle);
  // Into the bolt's frame: the inverse of its turn about y.
  auto local = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(screw.cos * v.x() - screw.sin * v.z(), v.y(),
                           screw.sin * v.x() + screw.cos * v.z());
  };
  const Eigen::Vector3d tilt(pose.tilt.x(), 0.0, pose.tilt.y());
  const Eigen::Vector3d origin(pose.offset.x(), pose.depth, pose.offset.y());
  screw.spin = local(tilt);
  screw.move = local(Eigen::Vector3d(pose.offset.x(), 0.0, pose.offset.y()) + tilt.cross(origin));
  screw.move.y() += screw.folded;
  return screw;
}

}  // namespace

void ThreadContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                      const PartSpec& outer, const SkinModelShape& outer_sms,
                                      const ModelSettings& settings) {
  const HelicoidGeometry& bolt = HelicoidGeometryOf(inner);
  const HelicoidGeometry& nut = HelicoidGeometryOf(outer);
  bolt_radius_ = bolt.outer_radius();
  const SurfaceGrid& grid = inner_sms.grid;
  if (outer_sms.grid.columns != grid.columns || grid.columns % 2 != 0) {
    throw UserError(
        "thread contact: the bolt's and the nut's grids must have the same even "
        "number of columns (strips per flank), found " +
        std::to_string(grid.columns) + " and " + std::to_string(outer_sms.grid.columns));
  }
  pitch_ = bolt.pitch();
  inverse_pitch_ = 1.0 / pitch_;
  lead_per_radian_ = pitch_ / kTwoPi;
  bolt_length_ = bolt.length();
  nut_length_ = nut.length();
  columns_ = grid.columns;
  rows_ = grid.rows;
  const double c = lead_per_radian_;
  const double k = std::tan(bolt.half_angle());
  const double rp = bolt.pitch_radius();
  const double bolt_turns = kTwoPi * bolt.turns();
  row_turn_ = bolt_turns / rows_;
  const int cells = grid.size();
  cells_.axial.resize(cells);
  cells_.turn.resize(cells);
  cells_.area.resize(cells);
  cells_.variation.resize(cells);
  cells_.nut_column.resize(cells);
  cells_.grid_cell.resize(cells);
  cells_.normal.resize(3, cells);
  cells_.normal_moment.resize(3, cells);
  cells_.slide.resize(3, cells);
  cells_.slide_moment.resize(3, cells);
  for (int i = 0; i < rows_; ++i) {
    // The grid's helix runs from the bolt's far end; along the same helicoid it is the bolt with
    // its leading end at y = 0 and turns theta <= 0.
    const double theta = (i + 0.5) * row_turn_ - bolt_turns;
    const double ct = std::cos(theta), st = std::sin(theta);
    const Eigen::Vector3d radial(ct, 0.0, -st), tangential(-st, 0.0, -ct);
    for (int j = 0; j < columns_; ++j) {
      const int cell = grid.index(i, j), at = i * columns_ + j;
      const double s = j < columns_ / 2 ? 1.0 : -1.0;
      const double r = std::hypot(grid.centre(0, cell), grid.centre(2, cell));
      const double y = c * theta + s * (0.25 * pitch_ - k * (r - rp));
      const Eigen::Vector3d p = r * radial + Eigen::Vector3d(0.0, y, 0.0);
      const Eigen::Vector3d n =
          (k * radial + Eigen::Vector3d(0.0, s, 0.0) - s * (c / r) * tangential).normalized();
      const Eigen::Vector3d h = (r * tangential + Eigen::Vector3d(0.0, c, 0.0)).normalized();
      cells_.axial[at] = y;
      cells_.turn[at] = theta;
      cells_.area[at] = grid.area[cell];
      cells_.variation[at] = inner_sms.variation[cell];
      cells_.nut_column[at] = j;
      cells_.grid_cell[at] = cell;
      cells_.normal.col(at) = n;
      cells_.normal_moment.col(at) = p.cross(n);
      cells_.slide.col(at) = h;
      cells_.slide_moment.col(at) = p.cross(h);
    }
  }
  const SurfaceGrid& nut_grid = outer_sms.grid;
  nut_row_turn_ = kTwoPi * nut.turns() / nut_grid.rows;
  nut_variation_.resize(nut_grid.rows, nut_grid.columns);
  for (int i = 0; i < nut_grid.rows; ++i) {
    for (int j = 0; j < nut_grid.columns; ++j) {
      nut_variation_(i, j) = outer_sms.variation[nut_grid.index(i, j)];
    }
  }
  // Bounds for skipping a flank that cannot touch (DoEvaluate): the largest bolt-minus-nut
  // deviation, the smallest |n_y| and the largest |p x n| of any cell.
  deviation_bound_ = cells_.variation.maxCoeff() - nut_variation_.minCoeff();
  row_area_.resize(rows_);
  for (int i = 0; i < rows_; ++i) row_area_[i] = cells_.area.segment(i * columns_, columns_).sum();
  axial_normal_min_ = cells_.normal.row(1).cwiseAbs().minCoeff();
  moment_arm_max_ = cells_.normal_moment.colwise().norm().maxCoeff();
  const ThreadOptions options = ThreadOptionsOf(settings);
  seat_ = options.joint.seat;
  weights_.clear();
  if (options.distribution == LoadDistribution::kSopwith) {
    // Sopwith's bars: the bolt's core (A_d3) and the nut's body, the annulus between the thread
    // and the nut's bearing diameter; the flank pair's stiffness per unit length is the engaged
    // thread's (the law's K) spread over the nut.
    const JointModel joint = MakeJointModel(inner, outer, options.joint);
    const double flank = settings.contact_stiffness > 0.0 ? settings.contact_stiffness
                                                          : 1.0 / joint.engaged_thread_compliance;
    const double d = bolt.diameter(), d3 = MinorDiameter(d, pitch_);
    const double body = MetricFastenerOf(d).nut_bearing_diameter;
    constexpr double kQuarterPi = 0.25 * std::numbers::pi;
    const double lambda =
        SopwithDecayRate(flank / nut_length_, inner.material.youngs_modulus * kQuarterPi * d3 * d3,
                         outer.material.youngs_modulus * kQuarterPi * (body * body - d * d));
    const double scale = lambda * nut_length_ / std::sinh(lambda * nut_length_);
    constexpr int kSamples = 256;
    weights_.resize(kSamples + 1);
    double weighted = 0.0, plain = 0.0;
    for (int n = 0; n <= kSamples; ++n) {
      const double y = nut_length_ * n / kSamples;
      weights_[n] = scale * std::cosh(lambda * (nut_length_ - y));
      // The countersinks' ramps (Share) take part of the first and last turns: the weights are
      // scaled to a mean of 1 over what the ramps leave, so the law's stiffness (taken for a
      // uniform load) holds for the whole nut.
      const double ramps = NutRamps(y);
      weighted += ramps * weights_[n];
      plain += ramps;
    }
    for (double& w : weights_) w *= plain / weighted;
  }
}

double ThreadContactAnalyzer::LoadWeight(double y) const noexcept {
  if (weights_.empty()) return 1.0;
  const int samples = static_cast<int>(weights_.size()) - 1;
  const double x = std::clamp(y / nut_length_, 0.0, 1.0) * samples;
  const int k = std::min(static_cast<int>(x), samples - 1);
  return weights_[k] + (x - k) * (weights_[k + 1] - weights_[k]);
}

ThreadContactAnalyzer::NutPlace ThreadContactAnalyzer::NutPlaceAt(double turn) const noexcept {
  const int rows = static_cast<int>(nut_variation_.rows());
  if (rows == 1) return {};
  const double x = turn / nut_row_turn_ - 0.5;
  NutPlace at;
  at.below = std::clamp(static_cast<int>(std::floor(x)), 0, rows - 2);
  at.above = at.below + 1;
  at.f = std::clamp(x - at.below, 0.0, 1.0);
  return at;
}

double ThreadContactAnalyzer::NutVariation(int column, const NutPlace& at) const noexcept {
  return (1.0 - at.f) * nut_variation_(at.below, column) + at.f * nut_variation_(at.above, column);
}

double ThreadContactAnalyzer::Weight(int i, double depth) const noexcept {
  return weights_.empty() ? 1.0 : LoadWeight(depth + cells_.axial[i]);
}

double ThreadContactAnalyzer::Geometric(int i, const ScrewPhase& screw) const noexcept {
  // (move + spin x p) . n = move . n + spin . (p x n).
  return screw.move.dot(cells_.normal.col(i)) + screw.spin.dot(cells_.normal_moment.col(i));
}

double ThreadContactAnalyzer::Interference(int i, const ScrewPhase& screw,
                                           double nut) const noexcept {
  return Geometric(i, screw) + screw.deviations * (cells_.variation[i] - nut);
}

double ThreadContactAnalyzer::InterferenceAt(int i, const ScrewPhase& screw,
                                             double angle) const noexcept {
  const NutPlace at = NutPlaceAt(cells_.turn[i] + angle + screw.shift);
  return Interference(i, screw, NutVariation(cells_.nut_column[i], at));
}

void ThreadContactAnalyzer::Rows(double depth, int* first, int* last) const noexcept {
  // A cell's centre lies within 3P/8 of its row's helix point c theta (ISO 68-1 flank band).
  const double margin = 0.375 * pitch_;
  const double bolt_turns = rows_ * row_turn_;
  auto row_of = [&](double y) { return (y / lead_per_radian_ + bolt_turns) / row_turn_ - 0.5; };
  const double lo = row_of(-depth - margin), hi = row_of(nut_length_ - depth + margin);
  *first = std::clamp(static_cast<int>(std::floor(lo)), 0, rows_);
  *last = std::clamp(static_cast<int>(std::ceil(hi)) + 1, 0, rows_);
}

void ThreadContactAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  const ScrewPhase screw = PhaseOf(pose, pitch_);
  int first = 0, last = 0;
  Rows(pose.depth, &first, &last);
  Eigen::Vector3d normal = Eigen::Vector3d::Zero(), normal_moment = Eigen::Vector3d::Zero();
  Eigen::Vector3d slide = Eigen::Vector3d::Zero(), slide_moment = Eigen::Vector3d::Zero();
  double volume = 0.0, largest = 0.0, area = 0.0;
  // d(normal_sum's x, z)/d(offset) in the bolt's frame: each touching cell's weighted area times
  // its normal's cross-section part with itself (an offset moves its interference by that part).
  double jxx = 0.0, jxz = 0.0, jzz = 0.0;
  // A flank whose every cell's interference is negative however its deviations, offset and tilt
  // fall is skipped: delta <= move_y n_y + |move_xz| + |spin| max|p x n| + deviations, and n_y has
  // the flank's sign (+ on A, - on B) and at least axial_normal_min_ in size. Under a load one
  // flank carries it and the other stands off by the play.
  const double reach = std::hypot(screw.move.x(), screw.move.z()) +
                       screw.spin.norm() * moment_arm_max_ +
                       screw.deviations * std::max(0.0, deviation_bound_);
  const int half = columns_ / 2;
  const int column_begin = screw.move.y() * axial_normal_min_ + reach <= 0.0 ? half : 0;
  const int column_end = -screw.move.y() * axial_normal_min_ + reach <= 0.0 ? half : columns_;
  for (int row = first; row < last; ++row) {
    // The nut's rows either side of this row's place on its helix, shared by the row's cells.
    const int begin = row * columns_;
    const NutPlace at = NutPlaceAt(cells_.turn[begin] + pose.angle + screw.shift);
    // A row a pitch clear of the nut's faces and of the bolt's end has every cell whole (its
    // cells lie within 3P/8 of the row's helix point): no ramps to weigh.
    const double centre = lead_per_radian_ * cells_.turn[begin];
    const double y = pose.depth + centre;
    const bool whole = y - 0.375 * pitch_ >= pitch_ && y + 0.375 * pitch_ <= nut_length_ - pitch_ &&
                       centre + 0.375 * pitch_ <= -pitch_;
    // The engaged area by the row's helix point's share (its cells' differ within the flank band).
    area += row_area_[row] * (whole ? 1.0 : ShareAt(pose.depth, centre));
    for (int j = column_begin; j < column_end; ++j) {
      const int i = begin + j;
      const double share = whole ? 1.0 : Share(i, pose.depth);
      if (share <= 0.0) continue;
      const double delta = Interference(i, screw, NutVariation(j, at));
      if (delta <= 0.0) continue;
      const double weighted = share * Weight(i, pose.depth) * cells_.area[i];
      const double a = weighted * delta;
      const double nx = cells_.normal(0, i), nz = cells_.normal(2, i);
      jxx += weighted * nx * nx;
      jxz += weighted * nx * nz;
      jzz += weighted * nz * nz;
      normal += a * cells_.normal.col(i);
      normal_moment += a * cells_.normal_moment.col(i);
      slide += a * cells_.slide.col(i);
      slide_moment += a * cells_.slide_moment.col(i);
      volume += a;
      largest = std::max(largest, delta);
    }
  }
  const Eigen::Vector3d origin(pose.offset.x(), pose.depth, pose.offset.y());
  out->normal_sum = Turn(normal, screw.cos, screw.sin);
  out->normal_moment = Turn(normal_moment, screw.cos, screw.sin) + origin.cross(out->normal_sum);
  out->slide_sum = Turn(slide, screw.cos, screw.sin);
  out->slide_moment = Turn(slide_moment, screw.cos, screw.sin) + origin.cross(out->slide_sum);
  out->engaged_area = area;
  out->engaged = area > 0.0;
  out->engaged_length =
      std::max(0.0, std::min(pose.depth, nut_length_) - std::max(pose.depth - bolt_length_, 0.0));
  out->interference = volume > 0.0;
  out->interference_volume = volume;
  out->max_interference = largest;
  out->pressure_resultant = Eigen::Vector2d(out->normal_sum.x(), out->normal_sum.z());
  // Into the nut's frame (Turn's rotation of x, z), exact for an untilted part.
  Eigen::Matrix2d turn;
  turn << screw.cos, screw.sin, -screw.sin, screw.cos;
  Eigen::Matrix2d local;
  local << jxx, jxz, jxz, jzz;
  out->resultant_jacobian = turn * local * turn.transpose();
  out->offset_distance = pose.offset.norm();
  out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
  out->stop_closure = std::isfinite(seat_) ? std::max(0.0, pose.depth - seat_) : 0.0;
}

bool ThreadContactAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                            std::vector<Eigen::Vector2d>* polygon) const {
  // Every engaged cell's interference is linear in the offset (untilted: exactly): delta_0 +
  // n . offset <= 0 is a half-plane, and the offsets that touch nothing their intersection.
  polygon->clear();
  MatingPose centred = pose;
  centred.offset.setZero();
  const ScrewPhase screw = PhaseOf(centred, pitch_);
  std::vector<double> angle, h;
  bool engaged = false;
  for (int i = 0; i < rows_ * columns_; ++i) {
    if (Share(i, pose.depth) <= 0.0) continue;
    engaged = true;
    const Eigen::Vector3d n = Turn(cells_.normal.col(i), screw.cos, screw.sin);
    const double across = std::hypot(n.x(), n.z());
    const double delta = InterferenceAt(i, screw, pose.angle);
    if (across < 1e-12) {
      if (delta > 0.0) return true;  // touching wherever the axis goes
      continue;
    }
    angle.push_back(std::atan2(n.z(), n.x()));
    h.push_back(-delta / across);
  }
  if (!engaged) return true;
  if (!IntersectHalfPlanes(angle, h, bolt_radius_, polygon)) polygon->clear();
  return true;
}

void ThreadContactAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                              Eigen::VectorXd* delta) const {
  const ScrewPhase screw = PhaseOf(pose, pitch_);
  delta->setZero(rows_ * columns_);
  for (int i = 0; i < rows_ * columns_; ++i) {
    if (Share(i, pose.depth) <= 0.0) continue;
    (*delta)[cells_.grid_cell[i]] = std::max(0.0, InterferenceAt(i, screw, pose.angle));
  }
}

}  // namespace fitfeel::thread
