#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"
#include "framework/model/texture_contact.h"
#include "surfaces/common/column_response_table.h"

namespace fitfeel::conical {

// Contact of a taper pin (inner) in a taper hole (outer) of the same taper.
//
// Pose: depth s is how far the pin's small end has passed the hole's entrance; offset is the
// pin axis' radial offset e (x, z). A pin cell at t from the small end sits at y = s - t in the
// hole. Both parts have the same taper, so the nominal radial clearance is uniform over the
// overlap: (L_hole - s) tan(alpha); zero when the small ends meet (s = L_hole) and an interference
// (s - L_hole) * C / 2 beyond (diametral: advance * C, DIN 7190). Per overlapping pin cell (i, j)
//   gap = (L_hole - s) tan(alpha) + V_hole(y, j) - V_pin(i, j) - e . u_j,   delta = max(0, -gap)
// with V_hole interpolated linearly between the hole's row centres (so the force is continuous in
// s). A pin cell's contact area is the slant area of the hole's nominal cone over the part of the
// cell's axial extent inside the hole (so cells enter and leave the overlap continuously, and the
// areas of a full overlap sum to the bore's area exactly). Both parts must share the column angles.
//
// Every contact, whether from clearance closed by the offset or from interference, is elastic
// (a Winkler bed: each cell's pressure is the Lame pressure of its own interference), so there is
// no separate clearance spring and the force is continuous at first contact. In `expected`
// texture mode a pin cell presses with the textures' expected interference at its gap
// (ContactTexture, framework/model/texture_contact.h) instead of max(0, -gap).
//
// This analyzer scans the pin's m x n cells at every evaluation (no allocation, O(m n)): it is the
// reference the tabulated ConicalContactAnalyzer (conical_contact_analyzer.h) is tested and
// benchmarked against, and what `model.options.contact: scan` selects.
class ConicalScanAnalyzer final : public ContactAnalyzer {
 public:
  double hole_length() const { return hole_length_; }
  double pin_length() const { return pin_length_; }
  double pin_pitch() const { return pin_pitch_; }
  double hole_pitch() const { return hole_pitch_; }
  int columns() const { return columns_; }
  // Unit direction u_j of column j in the cross-section (x, z).
  Eigen::Vector2d direction(int j) const { return direction_.col(j); }
  const ExpectedInterferenceTable& texture() const { return texture_; }
  // The nominal radial clearance (L_hole - s) tan(alpha) at depth s, m (negative: interference).
  double Clearance(double depth) const { return (hole_length_ - depth) * tan_alpha_; }
  // Total contact area of the overlap at depth s, m^2: what Evaluate reports as engaged_area.
  double EngagedArea(double depth) const noexcept;
  // Prepare-time (allocates): the overlapping cells of column j at depth s, with their gap at zero
  // offset less the clearance, i.e. V_hole - V_pin: the cell's gap at offset e is
  // Clearance(s) + gap - e . u_j.
  void ColumnCells(double depth, int column, std::vector<ColumnCell>* cells) const;

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override;
  // The offsets e with every overlapping cell's sharp gap >= 0: per column, e . u_j <=
  // Clearance(s) + min over the overlapping rows of (V_hole - V_pin). The texture's expected
  // interference is left out: the polygon is where the form lets the pin's axis go.
  bool DoAssemblySpace(const MatingPose& pose,
                       std::vector<Eigen::Vector2d>* polygon) const override;

 private:
  // Calls visit(column j, contact area, delta, pin row i) for every overlapping pin cell.
  template <class Visit>
  void ForEachCell(const MatingPose& pose, Visit&& visit) const noexcept;
  // Calls visit(row i, area, hole row k, k + 1, weight of k + 1) for every pin row overlapping the
  // hole at depth s.
  template <class Visit>
  void ForEachRow(double depth, Visit&& visit) const noexcept;
  // Slant area of the hole's nominal cone over [lo, hi] of its length, one column's share: exact
  // for a frustum, and continuous as a cell slides in or out of the hole.
  double SlantArea(double lo, double hi) const noexcept {
    return area_factor_ * (hi - lo) *
           (hole_small_diameter_ + taper_ * (hole_length_ - 0.5 * (lo + hi)));
  }

  int pin_rows_ = 0;
  int hole_rows_ = 0;
  int columns_ = 0;
  double pin_length_ = 0.0;
  double hole_length_ = 0.0;
  double pin_pitch_ = 0.0;   // axial height of a pin row, m
  double hole_pitch_ = 0.0;  // axial height of a hole row, m
  double tan_alpha_ = 0.0;
  double taper_ = 0.0;
  double hole_small_diameter_ = 0.0;
  double area_factor_ = 0.0;           // pi / cos(alpha) / n
  bool tiled_ = false;                 // the pin rows tile its length evenly
  Eigen::VectorXd pin_row_;            // t of each pin row centre
  Eigen::MatrixXd pin_v_;              // pin variation, rows x columns
  Eigen::MatrixXd hole_v_;             // hole variation, rows x columns
  Eigen::Matrix2Xd direction_;         // u_j = (cos beta_j, sin beta_j)
  ExpectedInterferenceTable texture_;  // sharp unless texture is `expected`
};

}  // namespace fitfeel::conical
