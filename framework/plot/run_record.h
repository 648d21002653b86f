#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/export.h"

namespace fitfeel::plot {

// Mean, minimum and maximum of a resistance over the constrained stage, N.
struct ResistanceStats {
  double mean = 0.0;
  double min = 0.0;
  double max = 0.0;
};

// What a plot needs from a run's summary.json (the output contract).
struct RunSummary {
  std::string scenario;                      // scenario name
  std::string law;                           // resistance law; empty when the run did not say
  std::optional<std::string> scenario_file;  // the scenario file the run came from
  std::optional<std::uint64_t> seed;
  ResistanceStats axial;   // axial_resistance_N
  ResistanceStats radial;  // radial_resistance_N
  // grid.inner / grid.outer {rows, columns} of the skin model shapes, when the run recorded them.
  std::optional<std::pair<int, int>> inner_grid;
  std::optional<std::pair<int, int>> outer_grid;
};

// The rows of a run's trace.csv in the constrained stage, in file order (SI is not used here on
// purpose: the columns keep the file's units, named in their suffixes).
struct ConstrainedTrace {
  std::vector<double> t_s;
  std::vector<double> depth_mm;
  std::vector<double> fx_N;
  std::vector<double> fy_N;
  std::vector<double> fz_N;
  // The device's position across the axis and the moving part's twist (MatingPose::angle), when
  // the trace has the columns x_mm, z_mm and angle_rad; empty otherwise.
  std::vector<double> x_mm;
  std::vector<double> z_mm;
  std::vector<double> angle_rad;
  // The moving part's radial offset in its pose (MatingPose::offset), when the trace has the
  // columns offset_x_um and offset_z_um (traces written before them do not); empty otherwise.
  // It differs from the device's x_mm, z_mm where the part was settled quasi-statically.
  std::vector<double> offset_x_um;
  std::vector<double> offset_z_um;
  // The torque on the moving part, when the trace has the columns tx_Nm, ty_Nm and tz_Nm; empty
  // otherwise.
  std::vector<double> tx_Nm;
  std::vector<double> ty_Nm;
  std::vector<double> tz_Nm;
  // A screw's (a thread scene's) tightening torque on the turning part and the joint's preload,
  // when the trace has the columns torque_Nm and preload_N; empty otherwise.
  std::vector<double> torque_Nm;
  std::vector<double> preload_N;
  // 1 from the tick the bearing face met (the column seated), when the trace has it.
  std::vector<double> seated;
};

struct RunRecord {
  std::filesystem::path dir;
  RunSummary summary;
  ConstrainedTrace trace;
};

// Readers of a run folder. Each throws UserError naming the file (and line, column or key) for a
// missing file, a malformed value or a missing key or column.
FITFEEL_API RunSummary LoadSummary(const std::filesystem::path& summary_json);
FITFEEL_API ConstrainedTrace LoadConstrainedTrace(const std::filesystem::path& trace_csv);
FITFEEL_API RunRecord LoadRun(const std::filesystem::path& dir);

}  // namespace fitfeel::plot
