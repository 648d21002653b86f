#pragma once

#include "surfaces/common/column_table_analyzer.h"
#include "surfaces/conical/conical_scan_analyzer.h"

namespace fitfeel::conical {

// The taper pin's contact (the model of ConicalScanAnalyzer, conical_scan_analyzer.h) tabulated in
// prepare by what a tick's result depends on, so that a tick costs O(n) instead of O(m n).
//
// At depth s and offset e, column j's cells have gaps Clearance(s) + g_ij(s) - e . u_j, where
// g_ij = V_hole - V_pin depends on s only through which pin rows overlap the hole and where they
// meet its rows. So per depth step s_k and column j the table holds the column's interference
// volume, resultant and largest interference as functions of z = e . u_j - Clearance(s)
// (ColumnResponseTable: sampled over the range where they are not simply zero or linear, exact
// beyond it). A tick evaluates, per column, z from the pose (the clearance exactly), the two
// neighbouring depth steps at that z and blends them linearly in s: continuous in depth and offset,
// nondecreasing in the offset towards a wall. The engaged area is the scan's closed form.
//
// Steps: half the finer of the two row pitches unless model.depth_step says otherwise (a pin row
// meets a new hole row centre, or crosses an end of the hole, every half pitch), over [0, L_pin +
// L_hole]; 33 samples of z per entry, filled on PrepareThreads() threads (bit for bit the same
// for any count; ColumnTableAnalyzer). The error against the scan is the z interpolation
// (ColumnResponseTable::VolumeErrorBound) at the steps, plus the depth blend between them (its
// curvature: a row's gap changes by the hole's form slope over a step); tested against the scan.
class ConicalContactAnalyzer final : public ColumnTableAnalyzer<ConicalScanAnalyzer> {
 public:
  double hole_length() const { return scan_.hole_length(); }
  double depth_step() const { return step(); }

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
};

}  // namespace fitfeel::conical
