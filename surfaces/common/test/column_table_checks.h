#pragma once

// Test helpers for a tabulated analyzer (surfaces/common/column_table_analyzer.h) against the scan
// it tabulates: the scan is the model, the table only changes how fast it is evaluated.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "framework/model/contact_analyzer.h"
#include "surfaces/common/column_response_table.h"

namespace fitfeel::test_support {

// The table's stated interpolation bound on the interference volume at entry `step`: the sum of
// its columns' bounds.
inline double TableVolumeBound(const ColumnResponseTable& table, int step) {
  double bound = 0.0;
  for (int j = 0; j < table.columns(); ++j) bound += table.VolumeErrorBound(step, j);
  return bound;
}

// At `pose`, the table's interference volume and resultant are within `bound` of the scan's
// (plus 1e-12 of the volume: rounding of the offset shifted by the clearance). Returns the two
// states for the caller's own checks.
template <class Analyzer>
std::pair<ContactState, ContactState> ExpectTableWithin(const Analyzer& analyzer,
                                                        const MatingPose& pose, double bound,
                                                        const std::string& where) {
  ContactState table, scan;
  analyzer.Evaluate(pose, &table);
  analyzer.scan().Evaluate(pose, &scan);
  EXPECT_NEAR(table.interference_volume, scan.interference_volume,
              bound + 1e-12 * scan.interference_volume)
      << where;
  EXPECT_LE((table.pressure_resultant - scan.pressure_resultant).norm(),
            bound + 1e-12 * scan.interference_volume)
      << where;
  return {table, scan};
}

// The table's interference volume's error against the scan's at `pose`, relative to the scan's
// volume but at least 0.1 um over the engaged area (below it the force is a few newtons of a
// joint whose press force reaches kilonewtons); 0 where nothing is engaged.
template <class Analyzer>
double TableRelativeError(const Analyzer& analyzer, const MatingPose& pose) {
  ContactState table, scan;
  analyzer.Evaluate(pose, &table);
  analyzer.scan().Evaluate(pose, &scan);
  const double scale = std::max(scan.interference_volume, 1e-7 * scan.engaged_area);
  if (!(scale > 0.0)) return 0.0;
  return std::abs(table.interference_volume - scan.interference_volume) / scale;
}

// Two analyzers give the same ticks bit for bit at 2000 poses next_pose(rng, one) draws.
template <class Analyzer, class NextPose>
void ExpectSameTicks(const Analyzer& one, const Analyzer& two, NextPose&& next_pose) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    const MatingPose pose = next_pose(rng, one);
    ContactState a, b;
    one.Evaluate(pose, &a);
    two.Evaluate(pose, &b);
    ASSERT_EQ(a.interference_volume, b.interference_volume) << trial;
    ASSERT_EQ(a.pressure_resultant, b.pressure_resultant) << trial;
    ASSERT_EQ(a.max_interference, b.max_interference) << trial;
    ASSERT_EQ(a.penetration, b.penetration) << trial;
    ASSERT_EQ(a.penetration_direction, b.penetration_direction) << trial;
    ASSERT_EQ(a.normal_force, b.normal_force) << trial;
  }
}

// Tables prepared on one and on two prepare threads (prepare(&analyzer)) give the same ticks bit
// for bit at 2000 poses next_pose(rng, analyzer) draws.
template <class Analyzer, class Prepare, class NextPose>
void ExpectSameTablesOnOneOrTwoThreads(Prepare&& prepare, NextPose&& next_pose) {
  Analyzer one, two;
  setenv("FITFEEL_PREPARE_THREADS", "1", 1);
  prepare(&one);
  setenv("FITFEEL_PREPARE_THREADS", "2", 1);
  prepare(&two);
  unsetenv("FITFEEL_PREPARE_THREADS");
  ExpectSameTicks(one, two, next_pose);
}

}  // namespace fitfeel::test_support
