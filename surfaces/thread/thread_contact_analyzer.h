#pragma once

#include <algorithm>
#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"

namespace fitfeel::thread {

struct ScrewPhase;

// Contact of a bolt's flanks with a nut's (docs/threads.md). In the nut's mating frame the bolt
// enters along +y; its leading end is at y = depth, and a turn by `angle` about +y advances the
// right-hand helix by P angle / 2 pi, so at depth = P angle / 2 pi (the screw phase u = depth -
// P angle / 2 pi is zero) both threads' nominal flanks coincide. A bolt cell's normal interference
// is the displacement of the pose from that screw (u along y, the offset across the axis) along
// the cell's normal, plus the bolt's variation there, minus the nut's at the same place of its
// helix (both skin model shapes: pitch diameter, pitch and flank-angle deviations).
//
// The phase is taken to the nearest turn and folded at a quarter pitch: a flank pushed further
// than P/4 into the other part's tooth rides towards its crest, so the interference falls back to
// zero at half a pitch, where the crests meet, and the force stays continuous. Flanks within one
// pitch of the bolt's end, of the nut's entrance and of its far face carry a share that rises
// linearly from zero: the end chamfer and the countersinks (ISO 4753, ISO 4032) cut the first
// turn's flanks away.
//
// Every sum is formed in the bolt's own frame from vectors fixed in prepare and turned into the
// nut's frame once: no trigonometry per cell. The nut's flank shift between two of its rows is
// interpolated linearly, so a pitch deviation moves the contact continuously.
class ThreadContactAnalyzer final : public ContactAnalyzer {
 public:
  // The flank stiffness's weight at `y` from the nut's bearing face (its entrance), after
  // Prepare: 1 for the uniform distribution; for model.options.distribution: sopwith, Sopwith's
  // cosh(lambda (L - y)), scaled to a mean of 1 over the flanks the countersinks leave.
  double LoadWeight(double y) const noexcept;

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override;
  // Per tick, from MatingPose::tilt.
  bool DoTakesHeldTilt() const override { return true; }
  bool DoAssemblySpace(const MatingPose& pose,
                       std::vector<Eigen::Vector2d>* polygon) const override;

 private:
  // The bolt's cells, row by row (turn angle), each row's strips flank A then flank B.
  struct Cells {
    Eigen::VectorXd axial;       // y of the centre in the bolt's frame (leading end at 0), m
    Eigen::VectorXd turn;        // helix angle in the bolt's frame (<= 0), rad
    Eigen::VectorXd area;        // m^2
    Eigen::VectorXd variation;   // the bolt's skin model shape, m
    Eigen::VectorXi nut_column;  // the nut's grid column of the same flank and strip
    Eigen::VectorXi grid_cell;   // the cell's index in the bolt's grid
    Eigen::Matrix3Xd normal, normal_moment, slide, slide_moment;  // bolt frame, about its origin
  };
  // Where a turn angle of the nut's helix falls between its grid's rows (linear interpolation).
  struct NutPlace {
    int below = 0, above = 0;
    double f = 0.0;
  };
  NutPlace NutPlaceAt(double turn) const noexcept;
  double NutVariation(int column, const NutPlace& at) const noexcept;
  // Interference of cell i at the screw phase `screw`, the nut's variation there being `nut`;
  // InterferenceAt finds that with the bolt turned by `angle` (a cell's own lookup; the tick's
  // loop looks up each row once).
  double Interference(int i, const ScrewPhase& screw, double nut) const noexcept;
  double InterferenceAt(int i, const ScrewPhase& screw, double angle) const noexcept;
  // Its part from the pose alone (the phase and the offset along the cell's normal).
  double Geometric(int i, const ScrewPhase& screw) const noexcept;
  // The share (0-1) of a flank point at `axial` in the bolt's frame at insertion `depth`: the
  // countersinks' ramps at both nut faces times the bolt's end chamfer's. Inline: the tick's
  // loop takes it for every cell of a row near a face.
  double ShareAt(double depth, double axial) const noexcept {
    return NutRamps(depth + axial) * std::clamp(-axial * inverse_pitch_, 0.0, 1.0);
  }
  // The nut's countersinks alone, at `y` from its entrance.
  double NutRamps(double y) const noexcept {
    return std::clamp(y * inverse_pitch_, 0.0, 1.0) *
           std::clamp((nut_length_ - y) * inverse_pitch_, 0.0, 1.0);
  }
  double Share(int i, double depth) const noexcept { return ShareAt(depth, cells_.axial[i]); }
  // The load distribution's weight of cell i at insertion `depth` (LoadWeight).
  double Weight(int i, double depth) const noexcept;
  // Row range [first, last) of the bolt whose cells can lie inside the nut at `depth`.
  void Rows(double depth, int* first, int* last) const noexcept;

  Cells cells_;
  double bolt_radius_ = 0.0;  // d/2, bounding the assembly space
  int columns_ = 0, rows_ = 0;
  double pitch_ = 0.0, inverse_pitch_ = 0.0, lead_per_radian_ = 0.0;
  double row_turn_ = 0.0;  // the bolt's turn angle per row, rad
  double nut_length_ = 0.0, bolt_length_ = 0.0;
  // rows x columns of the nut's grid, a row's columns together (read row by row).
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> nut_variation_;
  double nut_row_turn_ = 0.0;
  double seat_ = 0.0;  // depth at which the axial stop meets (infinity: none)
  double deviation_bound_ = 0.0, axial_normal_min_ = 0.0, moment_arm_max_ = 0.0;
  Eigen::VectorXd row_area_;  // each bolt row's cells' area summed
  // LoadWeight sampled evenly over the nut (empty: uniform).
  std::vector<double> weights_;
};

}  // namespace fitfeel::thread
