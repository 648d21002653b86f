#pragma once

#include "surfaces/common/column_table_analyzer.h"
#include "surfaces/spherical/spherical_scan_analyzer.h"

namespace fitfeel::spherical {

// The knuckle bearing's contact (the model of SphericalScanAnalyzer, spherical_scan_analyzer.h)
// tabulated in prepare by what a tick's result depends on, so that a tick costs O(n) instead of
// O(m n).
//
// With the ball turned by theta and its centre offset by e, socket cell (i, j) has the gap
// g_ij(theta) - cos(lat_i) e . u_j: the offset enters each column through one scalar, x = e . u_j,
// and theta through the ball's variation under the column. So per rotation step theta_q and socket
// column j the table holds the column's interference volume, resultant (weighted by cos(lat)) and
// largest interference as functions of x (ColumnResponseTable: sampled where they are not simply
// zero or linear, exact beyond). A tick evaluates, per column, the two neighbouring rotation steps
// at x and blends them linearly in theta (periodically): continuous in rotation and offset,
// nondecreasing in the offset towards the socket.
//
// Steps: two per column pitch over the full turn, 33 samples of x per entry; the entries are
// filled on PrepareThreads() threads, bit for bit the same for any count, and only within a run's
// ModelSettings::angular_reach where it bounds the turn (beyond it an entry answers no contact).
// Between two steps each cell's gap is linear in theta (the ball's variation is interpolated
// linearly between its columns), so the blend's error is second order in the ball's change over
// half a pitch; one step per pitch would miss how partial contact changes half a pitch off the
// columns, where a lobed ball's lobes sit between the socket's cells. The error against the scan is
// the x interpolation (ColumnResponseTable::VolumeErrorBound) at the steps, plus that blend between
// them; tested against the scan.
class SphericalContactAnalyzer final : public ColumnTableAnalyzer<SphericalScanAnalyzer> {
 public:
  static constexpr int kStepsPerColumn = 2;

  double angle_step() const { return step(); }

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
};

}  // namespace fitfeel::spherical
