#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"
#include "framework/model/texture_contact.h"
#include "surfaces/common/column_response_table.h"

namespace fitfeel::spherical {

// Contact of a ball (inner ring, inner) in a socket (outer ring, outer) of a spherical plain
// bearing. The ball is captive: it cannot leave the socket along the axis, so the pose's depth is
// not a degree of freedom here (it is ignored, and the parts are always engaged). The pose's angle
// is the ball's rotation about the bearing axis y, its offset (x, z) the radial displacement e of
// the ball's centre from the socket's.
//
// Per socket cell k (row i at height y, column j at beta_j, unit normal n_k from the centre):
//   gap = V_socket(k) - V_ball(y, beta_j - angle) - e . n_k,     delta = max(0, -gap)
// with the ball's variation interpolated bilinearly (in y between its rows, in beta periodically
// between its columns) at the material point that the rotation has brought under the cell, so the
// contact is continuous in the angle. The socket's band is the contact band (the ball's is wider,
// CheckPair requires it). Every contact is elastic (Winkler bed of thick-shell pressures), so there
// is no separate clearance spring and the force is continuous at first contact. The texture
// enters through ContactTexture (framework/model/texture_contact.h): in `expected` mode a socket
// cell's interference is the expected one at its gap, not max(0, -gap).
//
// Sums reported: interference_volume = sum delta * ds, pressure_resultant = sum delta * ds *
// (n_x, n_z) (the axial component of the resultant is not reported: ContactState has no field
// for it, and it vanishes for a band symmetric about the equator unless the form is asymmetric).
//
// This analyzer scans the socket's m x n cells at every evaluation (no allocation, O(m n)): the
// reference that the tabulated SphericalContactAnalyzer (spherical_contact_analyzer.h) is tested
// and benchmarked against.
//
// The interference map (for pictures, not the tick) is over the ball's cells, as the interface
// asks: the ball's material cell (row r, column c) lies, after the rotation, at beta_c + angle
// under the socket, whose variation is interpolated there (in y between its row centres, clamped to
// the end rows; in beta periodically). Ball cells whose centre lies outside the socket's band touch
// nothing and are zero.
class SphericalScanAnalyzer final : public ContactAnalyzer {
 public:
  int rows() const { return rows_; }
  int columns() const { return columns_; }
  double engaged_area() const { return cell_area_ * rows_ * columns_; }
  double width() const { return width_; }
  const ExpectedInterferenceTable& texture() const { return texture_; }
  // Unit direction u_j of socket column j in the cross-section (x, z): a cell's normal projects
  // on the cross-section as cos(latitude) * u_j.
  Eigen::Vector2d direction(int j) const;
  // Prepare-time (allocates): the cells of socket column j with the ball turned by `angle`, with
  // their gap at zero offset and cosine = cos(latitude): a cell's gap at offset e is
  // gap - cosine * e . u_j.
  void ColumnCells(double angle, int column, std::vector<ColumnCell>* cells) const;

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override;
  // The centre offsets e with every socket cell's sharp gap >= 0 at the pose's angle: per column,
  // e . u_j <= min over rows of gap / cos(latitude). The texture's expected interference is left
  // out: the polygon is where the form lets the ball's centre go.
  bool DoAssemblySpace(const MatingPose& pose,
                       std::vector<Eigen::Vector2d>* polygon) const override;

 private:
  template <class Visit>
  void ForEachCell(const MatingPose& pose, Visit&& visit) const noexcept;
  // The ball's variation under socket cell (i, j) with the ball turned by `angle`.
  double BallVariationUnder(int i, int j, double angle) const noexcept;

  int rows_ = 0;     // socket rows
  int columns_ = 0;  // shared column count
  double width_ = 0.0;
  double cell_area_ = 0.0;
  Eigen::MatrixXd socket_v_;  // rows x columns
  Eigen::MatrixXd ball_v_;    // ball rows x columns
  // Ball rows bracketing each socket row, and the weight of the upper one (prepare-time).
  std::vector<int> ball_row_;
  std::vector<double> ball_row_weight_;
  Eigen::Matrix3Xd normal_;  // socket cell normals
  // For the ball-cell interference map (prepare-time): per ball row, whether its centre lies in
  // the socket's band, the socket rows bracketing it and the upper one's weight; the ball's
  // normals.
  std::vector<char> ball_row_in_band_;
  std::vector<int> socket_row_;
  std::vector<double> socket_row_weight_;
  Eigen::Matrix3Xd ball_normal_;
  ExpectedInterferenceTable texture_;  // sharp unless texture is `expected`
};

}  // namespace fitfeel::spherical
