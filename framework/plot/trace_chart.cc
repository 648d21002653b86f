#include "framework/plot/trace_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "framework/core/error.h"

namespace fitfeel::plot {

void DecimateKeepingPeaks(std::vector<double>* x, std::vector<double>* y, std::size_t max_points) {
  const std::size_t n = x->size();
  if (n <= max_points || max_points < 2) return;
  const std::size_t buckets = max_points / 2;
  std::vector<double> out_x, out_y;
  out_x.reserve(2 * buckets);
  out_y.reserve(2 * buckets);
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = b * n / buckets;
    const std::size_t end = (b + 1) * n / buckets;
    std::size_t low = begin, high = begin;
    for (std::size_t k = begin; k < end; ++k) {
      if ((*y)[k] < (*y)[low]) low = k;
      if ((*y)[k] > (*y)[high]) high = k;
    }
    const std::size_t first = std::min(low, high), second = std::max(low, high);
    out_x.push_back((*x)[first]);
    out_y.push_back((*y)[first]);
    if (second != first) {
      out_x.push_back((*x)[second]);
      out_y.push_back((*y)[second]);
    }
  }
  *x = std::move(out_x);
  *y = std::move(out_y);
}

std::string FormatNewtons(double value) {
  // Whole newtons from 1000 N up, three significant digits below (0.000123 N stays readable).
  char buffer[64];
  value += 0.0;                    // -0 (a sign without magnitude) prints as 0
  if (std::abs(value) >= 999.5) {  // from where %.3g would print 1e+03
    std::snprintf(buffer, sizeof buffer, "%.0f N", value);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.3g N", value);
  }
  return buffer;
}

namespace {

std::string RunName(const RunSummary& summary) {
  return summary.scenario + (summary.law.empty() ? "" : " · law " + summary.law);
}

std::string StatsText(const ResistanceStats& stats) {
  return "mean " + FormatNewtons(stats.mean) + ", min " + FormatNewtons(stats.min) + ", max " +
         FormatNewtons(stats.max);
}

}  // namespace

LineChart MakeTraceChart(const std::vector<RunRecord>& runs, bool log_scale) {
  if (runs.empty()) throw UserError("no run folder to plot");
  // Parts mated by rotation (a knuckle bearing) keep one depth throughout: against depth their
  // curves would collapse onto a vertical line, so such runs, and any drawn beside them, are
  // drawn against the run's time.
  bool by_time = false;
  for (const auto& run : runs) {
    const auto [low, high] =
        std::minmax_element(run.trace.depth_mm.begin(), run.trace.depth_mm.end());
    by_time = by_time || *high - *low <= 0.0;
  }
  const std::string x_label = by_time ? "time (s)" : "insertion depth (mm)";
  LineChart chart;
  chart.title = by_time ? "Assembly resistance over the run (constrained stage; the depth does "
                          "not change, so against time)"
                        : "Assembly resistance along the insertion (constrained stage)";
  LinePanel axial{"Axial resistance", x_label, "axial resistance |F_y| (N)", true, log_scale, {}};
  LinePanel radial{"Radial resistance", x_label, "radial resistance sqrt(F_x² + F_z²) (N)", true,
                   log_scale,           {}};
  for (const auto& run : runs) {
    const auto& trace = run.trace;
    std::vector<double> depth = by_time ? trace.t_s : trace.depth_mm, fy(trace.fy_N.size()),
                        fr(trace.fx_N.size());
    for (std::size_t k = 0; k < fy.size(); ++k) {
      fy[k] = std::abs(trace.fy_N[k]);
      fr[k] = std::hypot(trace.fx_N[k], trace.fz_N[k]);
    }
    std::vector<double> depth_radial = depth;
    DecimateKeepingPeaks(&depth, &fy, kMaxCurvePoints);
    DecimateKeepingPeaks(&depth_radial, &fr, kMaxCurvePoints);
    const std::string name = RunName(run.summary);
    axial.series.push_back({name + ": " + StatsText(run.summary.axial), depth, fy});
    radial.series.push_back({name + ": " + StatsText(run.summary.radial), depth_radial, fr});
  }
  chart.panels = {std::move(axial), std::move(radial)};
  return chart;
}

LineChart MakeTorqueChart(const std::vector<RunRecord>& runs) {
  if (runs.empty()) throw UserError("no run folder to plot");
  LineChart chart;
  chart.title = "Tightening: torque and preload along the turn (constrained stage)";
  // Where every run's nut met the face, the angle counts from there and the chart starts a
  // quarter turn before it: the tightening spans tens of degrees at the end of many turns.
  bool seated = true;
  for (const auto& run : runs) {
    const auto& s = run.trace.seated;
    seated = seated && !s.empty() && s.size() == run.trace.angle_rad.size() && s.back() > 0.5;
  }
  const std::string x_label =
      seated ? "turn past the bearing face's meeting (deg)" : "turn angle (deg)";
  LinePanel torque{"Torque", x_label, "torque on the turning part (N·m)", true, false, {}};
  LinePanel preload{"Preload", x_label, "preload (N)", true, false, {}};
  for (const auto& run : runs) {
    const auto& trace = run.trace;
    if (trace.torque_Nm.empty() || trace.angle_rad.empty()) {
      throw UserError("the trace in " + run.dir.string() +
                      " has no torque_Nm, preload_N or angle_rad column: --torque plots a "
                      "screw's run (a thread scene)");
    }
    std::vector<double> angle, torque_y, preload_y;
    double origin = 0.0;  // the angle at which the face met, deg
    if (seated) {
      std::size_t k = 0;
      while (trace.seated[k] < 0.5) ++k;
      origin = trace.angle_rad[k] * 180.0 / std::numbers::pi;
    }
    for (std::size_t k = 0; k < trace.angle_rad.size(); ++k) {
      const double x = trace.angle_rad[k] * 180.0 / std::numbers::pi - origin;
      if (seated && x < -90.0) continue;
      angle.push_back(x);
      torque_y.push_back(trace.torque_Nm[k]);
      preload_y.push_back(trace.preload_N[k]);
    }
    const std::string name = RunName(run.summary);
    char last[96];
    std::snprintf(last, sizeof last, ": %.3g N·m at the end", torque_y.back());
    const std::string torque_label = name + last;
    const std::string preload_label = name + ": " + FormatNewtons(preload_y.back()) + " at the end";
    std::vector<double> angle_preload = angle;
    DecimateKeepingPeaks(&angle, &torque_y, kMaxCurvePoints);
    DecimateKeepingPeaks(&angle_preload, &preload_y, kMaxCurvePoints);
    torque.series.push_back({torque_label, angle, torque_y});
    preload.series.push_back({preload_label, angle_preload, preload_y});
  }
  chart.panels = {std::move(torque), std::move(preload)};
  return chart;
}

}  // namespace fitfeel::plot
