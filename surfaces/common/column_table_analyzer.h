#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"
#include "surfaces/common/column_response_table.h"

namespace fitfeel {

// A contact analyzer that answers a tick from a ColumnResponseTable of its scan analyzer's columns
// instead of scanning every cell: O(n) per tick instead of O(m n). The table's entries are steps
// of one pose parameter (a taper pin's depth, a ball's rotation), so a tick blends the two entries
// that bracket the pose. `Scan` is the plugin's scan analyzer, the reference the table is tested
// against, with
//   int columns() const;
//   Eigen::Vector2d direction(int j) const;                 // u_j in the cross-section (x, z)
//   const ExpectedInterferenceTable& texture() const;
//   void ColumnCells(double parameter, int j, std::vector<ColumnCell>* cells) const;
// The interference map and the assembly space are the scan's (neither is on the tick).
// Header-only: a plugin links nothing more and exports nothing more.
template <class Scan>
class ColumnTableAnalyzer : public ContactAnalyzer {
 public:
  // Samples of x = offset . u_j per entry; the interpolation's error bound falls with the square
  // of their spacing (ColumnResponseTable::VolumeErrorBound).
  static constexpr int kSamples = 33;

  const Scan& scan() const { return scan_; }
  const ColumnResponseTable& table() const { return table_; }

 protected:
  // Prepare, once scan_ is prepared: entry k of column j holds the scan's cells of column j at
  // parameter k * step, filled on PrepareThreads() threads (bit for bit the same for any count);
  // only the steps `wanted` where it names any (the others answer no contact: a run's device
  // never takes the part there).
  void Tabulate(int steps, double step, const std::vector<int>& wanted = {}) {
    step_ = step;
    const int columns = scan_.columns();
    table_ = ColumnResponseTable(steps, columns, kSamples, scan_.texture());
    const auto cells = [this, step](int k, int j, std::vector<ColumnCell>* out) {
      scan_.ColumnCells(k * step, j, out);
    };
    if (wanted.empty()) {
      table_.FillAll(cells);
    } else {
      table_.FillSteps(wanted, cells);
    }
    direction_.resize(2, columns);
    for (int j = 0; j < columns; ++j) direction_.col(j) = scan_.direction(j);
  }

  // The entries and the parameter's step between two of them.
  int steps() const { return table_.steps(); }
  double step() const { return step_; }

  // Per tick: adds the columns' sums at x_j = offset . u_j - shift, blended between entries a and
  // b with weight t of b (ColumnResponseTable::Blend).
  void Blend(int a, int b, double t, const MatingPose& pose, double shift,
             ContactState* out) const noexcept {
    table_.Blend(a, b, t, direction_, pose.offset, shift, out);
  }

  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override {
    scan_.InterferenceMap(pose, delta);
  }
  bool DoAssemblySpace(const MatingPose& pose,
                       std::vector<Eigen::Vector2d>* polygon) const override {
    return scan_.AssemblySpace(pose, polygon);
  }

  Scan scan_;

 private:
  ColumnResponseTable table_;
  double step_ = 0.0;
  Eigen::Matrix2Xd direction_;
};

}  // namespace fitfeel
