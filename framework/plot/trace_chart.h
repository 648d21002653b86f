#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/plot/figure.h"
#include "framework/plot/run_record.h"

namespace fitfeel::plot {

// Curves of more points than a screen has pixels only slow the renderer down; above this many
// points a curve is reduced to the minimum and maximum of each of max_points / 2 buckets, which
// keeps every peak a reader could see.
inline constexpr std::size_t kMaxCurvePoints = 8000;

// Reduces (x, y) to at most `max_points` points (min/max per bucket, in the original order).
FITFEEL_API void DecimateKeepingPeaks(std::vector<double>* x, std::vector<double>* y,
                                      std::size_t max_points);

// "12.3 N" with a precision that suits the magnitude.
FITFEEL_API std::string FormatNewtons(double value);

// The resistance chart of `fitfeel plot trace`: axial resistance |F_y| (top) and radial resistance
// sqrt(F_x^2 + F_z^2) (bottom) against insertion depth, one curve per run, labelled with the
// scenario, the law and the summary's mean/min/max. `log_scale` draws both force axes
// logarithmic, for runs whose resistances differ by orders of magnitude (an interference fit
// beside a clearance fit). When a run's depth never changes (parts mated by rotation), every
// curve is drawn against the run's time instead, and the title says so. Throws UserError for no
// runs.
FITFEEL_API LineChart MakeTraceChart(const std::vector<RunRecord>& runs, bool log_scale = false);

// The tightening chart of `fitfeel plot trace --torque`: a screw's torque on the turning part
// (top) and the joint's preload (bottom) against the part's turn angle in degrees, one curve per
// run, labelled with the scenario and the torque and preload where the run ended. Where every run
// seated its nut, the angle counts from the bearing face's meeting and starts a quarter turn before
// it. Throws UserError
// for no runs, or for a run whose trace has no torque_Nm, preload_N or angle_rad column (not a
// screw's run).
FITFEEL_API LineChart MakeTorqueChart(const std::vector<RunRecord>& runs);

}  // namespace fitfeel::plot
