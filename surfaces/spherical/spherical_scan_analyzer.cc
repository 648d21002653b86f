#include "surfaces/spherical/spherical_scan_analyzer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/model/convex_polygon.h"
#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {

void SphericalScanAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                      const PartSpec& outer, const SkinModelShape& outer_sms,
                                      const ModelSettings& settings) {
  texture_ = ContactTexture(inner.texture, outer.texture, settings.texture);
  GeometryOf(inner);
  const SphericalGeometry& socket = GeometryOf(outer);
  const SurfaceGrid& bg = inner_sms.grid;
  const SurfaceGrid& sg = outer_sms.grid;
  revolution::CheckSharedColumns(bg, sg, "ball and socket");
  rows_ = sg.rows;
  columns_ = sg.columns;
  width_ = socket.width();
  cell_area_ = sg.area(0);
  socket_v_.resize(rows_, columns_);
  for (int i = 0; i < rows_; ++i) {
    for (int j = 0; j < columns_; ++j) socket_v_(i, j) = outer_sms.variation(sg.index(i, j));
  }
  ball_v_.resize(bg.rows, columns_);
  for (int i = 0; i < bg.rows; ++i) {
    for (int j = 0; j < columns_; ++j) ball_v_(i, j) = inner_sms.variation(bg.index(i, j));
  }
  ball_row_.resize(rows_);
  ball_row_weight_.resize(rows_);
  const double ball_pitch = bg.rows > 1 ? bg.row_position(1) - bg.row_position(0) : 1.0;
  for (int i = 0; i < rows_; ++i) {
    const double u =
        bg.rows > 1
            ? std::clamp((sg.row_position(i) - bg.row_position(0)) / ball_pitch, 0.0, bg.rows - 1.0)
            : 0.0;
    ball_row_[i] = std::min(static_cast<int>(u), std::max(bg.rows - 2, 0));
    ball_row_weight_[i] = bg.rows > 1 ? u - ball_row_[i] : 0.0;
  }
  normal_ = sg.normal;

  ball_normal_ = bg.normal;
  ball_row_in_band_.assign(bg.rows, 0);
  socket_row_.assign(bg.rows, 0);
  socket_row_weight_.assign(bg.rows, 0.0);
  const double half_band = 0.5 * width_;
  const double socket_pitch = rows_ > 1 ? sg.row_position(1) - sg.row_position(0) : 1.0;
  for (int r = 0; r < bg.rows; ++r) {
    const double y = bg.row_position(r);
    // A relative tolerance keeps a ball row centred on the band's edge (equal pitches) inside.
    ball_row_in_band_[r] = std::abs(y) <= half_band * (1.0 + 1e-9) ? 1 : 0;
    const double u =
        rows_ > 1 ? std::clamp((y - sg.row_position(0)) / socket_pitch, 0.0, rows_ - 1.0) : 0.0;
    socket_row_[r] = std::min(static_cast<int>(u), std::max(rows_ - 2, 0));
    socket_row_weight_[r] = rows_ > 1 ? u - socket_row_[r] : 0.0;
  }
}

double SphericalScanAnalyzer::BallVariationUnder(int i, int j, double angle) const noexcept {
  const double pitch = 2.0 * M_PI / columns_;
  const int last_ball_row = static_cast<int>(ball_v_.rows()) - 1;
  // The ball's material point under socket column j was at beta_j - angle before the rotation.
  double u = std::fmod(j - angle / pitch, static_cast<double>(columns_));
  if (u < 0.0) u += columns_;
  int j0 = static_cast<int>(u);
  const double fj = u - j0;
  j0 %= columns_;
  const int j1 = (j0 + 1) % columns_;
  const int r0 = ball_row_[i];
  const int r1 = std::min(r0 + 1, last_ball_row);
  const double fr = ball_row_weight_[i];
  return (1.0 - fr) * ((1.0 - fj) * ball_v_(r0, j0) + fj * ball_v_(r0, j1)) +
         fr * ((1.0 - fj) * ball_v_(r1, j0) + fj * ball_v_(r1, j1));
}

template <class Visit>
void SphericalScanAnalyzer::ForEachCell(const MatingPose& pose, Visit&& visit) const noexcept {
  for (int j = 0; j < columns_; ++j) {
    for (int i = 0; i < rows_; ++i) {
      const double ball_v = BallVariationUnder(i, j, pose.angle);
      const int k = i * columns_ + j;
      const double shift = pose.offset.x() * normal_(0, k) + pose.offset.y() * normal_(2, k);
      const double gap = socket_v_(i, j) - ball_v - shift;
      visit(k, texture_(gap));
    }
  }
}

Eigen::Vector2d SphericalScanAnalyzer::direction(int j) const {
  const Eigen::Vector2d n(normal_(0, j), normal_(2, j));  // row 0's cell of column j
  return n / n.norm();
}

void SphericalScanAnalyzer::ColumnCells(double angle, int j, std::vector<ColumnCell>* cells) const {
  cells->clear();
  for (int i = 0; i < rows_; ++i) {
    const int k = i * columns_ + j;
    const double cosine = std::hypot(normal_(0, k), normal_(2, k));
    cells->push_back({cell_area_, cosine, socket_v_(i, j) - BallVariationUnder(i, j, angle)});
  }
}

void SphericalScanAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  // A non-finite pose (a device glitch) is no contact rather than NaN forces.
  if (!std::isfinite(pose.angle) || !pose.offset.allFinite()) return;
  out->engaged = true;
  out->engaged_length = width_;
  out->engaged_area = cell_area_ * rows_ * columns_;
  out->offset_distance = pose.offset.norm();
  out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
  ForEachCell(pose, [&](int k, double delta) {
    if (delta > 0.0) {
      out->interference_volume += delta * cell_area_;
      out->max_interference = std::max(out->max_interference, delta);
      out->pressure_resultant += delta * cell_area_ * Eigen::Vector2d(normal_(0, k), normal_(2, k));
    }
  });
  out->interference = out->interference_volume > 0.0;
}

void SphericalScanAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                              Eigen::VectorXd* delta) const {
  const int ball_rows = static_cast<int>(ball_v_.rows());
  delta->setZero(static_cast<Eigen::Index>(ball_rows) * columns_);
  if (!std::isfinite(pose.angle) || !pose.offset.allFinite()) {
    throw UserError("interference map of a non-finite ball rotation or offset");
  }
  const double pitch = 2.0 * M_PI / columns_;
  const double cos_a = std::cos(pose.angle), sin_a = std::sin(pose.angle);
  const int last_socket_row = rows_ - 1;
  for (int c = 0; c < columns_; ++c) {
    // Ball column c has turned to beta_c + angle: between socket columns j0 and j1.
    double u = std::fmod(c + pose.angle / pitch, static_cast<double>(columns_));
    if (u < 0.0) u += columns_;
    int j0 = static_cast<int>(u);
    const double fj = u - j0;
    j0 %= columns_;
    const int j1 = (j0 + 1) % columns_;
    for (int r = 0; r < ball_rows; ++r) {
      if (!ball_row_in_band_[r]) continue;
      const int s0 = socket_row_[r];
      const int s1 = std::min(s0 + 1, last_socket_row);
      const double fs = socket_row_weight_[r];
      const double socket_v =
          (1.0 - fs) * ((1.0 - fj) * socket_v_(s0, j0) + fj * socket_v_(s0, j1)) +
          fs * ((1.0 - fj) * socket_v_(s1, j0) + fj * socket_v_(s1, j1));
      const int k = r * columns_ + c;
      // The ball's normal turned with it about y.
      const double nx = cos_a * ball_normal_(0, k) - sin_a * ball_normal_(2, k);
      const double nz = sin_a * ball_normal_(0, k) + cos_a * ball_normal_(2, k);
      const double gap = socket_v - ball_v_(r, c) - (pose.offset.x() * nx + pose.offset.y() * nz);
      (*delta)(k) = texture_(gap);
    }
  }
}

bool SphericalScanAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                            std::vector<Eigen::Vector2d>* polygon) const {
  polygon->clear();
  if (!std::isfinite(pose.angle)) return true;
  std::vector<double> angle(columns_), h(columns_, std::numeric_limits<double>::infinity());
  for (int j = 0; j < columns_; ++j) {
    const Eigen::Vector2d u = direction(j);
    angle[j] = std::atan2(u.y(), u.x());
    for (int i = 0; i < rows_; ++i) {
      const int k = i * columns_ + j;
      const double cosine = std::hypot(normal_(0, k), normal_(2, k));
      const double gap = socket_v_(i, j) - BallVariationUnder(i, j, pose.angle);
      h[j] = std::min(h[j], gap / cosine);
    }
  }
  // Columns all round the axis close the polygon; the bound only guards degenerate grids.
  if (!IntersectHalfPlanes(angle, h, width_, polygon)) polygon->clear();
  return true;
}

}  // namespace fitfeel::spherical
