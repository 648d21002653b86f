#include "framework/plot/scene_charts.h"

#include <cstdio>
#include <vector>

#include "framework/core/error.h"
#include "framework/plot/sms_chart.h"

namespace fitfeel::plot {

HeatMapChart MakeSceneSmsChart(const std::string& scenario, const PartSpec& inner,
                               const SkinModelShape& inner_sms, const PartSpec& outer,
                               const SkinModelShape& outer_sms, bool translational,
                               const std::string& only_part) {
  if (!only_part.empty()) {
    if (only_part == inner.name) {
      return MakeSmsChart(scenario, {MakeSkinProfileMap(inner, inner_sms)});
    }
    if (only_part == outer.name) {
      return MakeSmsChart(scenario, {MakeSkinProfileMap(outer, outer_sms)});
    }
    throw UserError("scenario '" + scenario + "' has no part '" + only_part + "'; its parts are '" +
                    inner.name + "' and '" + outer.name + "'");
  }
  std::vector<HeatMap> maps = {MakeSkinProfileMap(inner, inner_sms),
                               MakeSkinProfileMap(outer, outer_sms)};
  std::string omitted;
  if (!translational) {
    omitted = "no tolerance-space map: the parts mate by rotation, not by insertion";
  } else {
    try {
      const double depth = FullInsertionDepth(inner_sms, outer_sms);
      char where[96];
      std::snprintf(where, sizeof where, "at full insertion (depth %g mm)", depth * 1e3);
      maps.push_back(MakeToleranceSpaceMap(
          inner, outer, ToleranceSpaceAtDepth(inner_sms, outer_sms, depth), where));
    } catch (const UserError& e) {
      omitted = std::string("no tolerance-space map: ") + e.what();
    }
  }
  HeatMapChart chart = MakeSmsChart(scenario, std::move(maps));
  if (!omitted.empty()) chart.subtitle.push_back(omitted);
  return chart;
}

PressureMapData MakePressureData(const RunRecord& run, double depth_mm,
                                 const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                                 const SurfaceGrid& inner_grid, Role moving) {
  const ConstrainedTrace& trace = run.trace;
  const std::size_t row = RowAtDepth(trace, depth_mm);
  MatingPose pose;
  pose.depth = depth_mm * 1e-3;
  PressureMapData data;
  if (!trace.x_mm.empty()) pose.angle = trace.angle_rad[row];
  if (!trace.offset_x_um.empty()) {
    pose.offset = Eigen::Vector2d(trace.offset_x_um[row], trace.offset_z_um[row]) * 1e-6;
  } else if (!trace.x_mm.empty()) {
    // Traces written before the pose's offset had columns: the device's position is the offset
    // except where the constrained stage settled the part under a radial load.
    pose.offset = Eigen::Vector2d(trace.x_mm[row], trace.z_mm[row]) * 1e-3;
    // A subtitle line: short enough for the chart's width.
    data.pose_note =
        "pose offset taken from the device position (old trace without offset_x_um, "
        "offset_z_um)";
  } else {
    data.pose_note = "no radial offset or twist: the trace has no pose columns";
  }
  data.scenario = run.summary.scenario;
  data.law = run.summary.law;
  data.depth_mm = depth_mm;
  data.grid = inner_grid;
  analyzer.InterferenceMap(AnalyzerPose(pose, moving), &data.interference);
  try {
    data.pressure_per_interference = law.PressurePerInterference();
  } catch (const UnsupportedError&) {
    // Say which law and why: the reader asked for a picture, not about the law's interface.
    throw UnsupportedError(
        "no pressure map for run '" + run.summary.scenario + "': its law '" +
        (run.summary.law.empty() ? std::string("(unnamed)") : run.summary.law) +
        "' gives no contact pressure per unit interference (a law that ignores the skin model "
        "shapes, like the paper's VE1, has no pressure field over them)");
  }
  data.fx_N = trace.fx_N[row];
  data.fy_N = trace.fy_N[row];
  data.fz_N = moving == Role::kOuter ? -trace.fz_N[row] : trace.fz_N[row];
  data.force_depth_mm = trace.depth_mm[row];
  return data;
}

}  // namespace fitfeel::plot
