#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/export.h"
#include "framework/device/device_report.h"
#include "framework/device/recording.h"
#include "framework/runtime/tick_record.h"

namespace fitfeel {

// What the outputs say about the run besides its ticks.
struct RunInfo {
  std::string scenario;
  std::filesystem::path scenario_file;
  std::vector<std::string> features;  // a several-feature scene's, in order
  bool screw = false;                 // a screw scene: summary.json's `thread`
  std::uint64_t seed = 0;
  std::string surface;
  std::string law;
  std::string device;
  std::string clock;      // "virtual" | "realtime"
  double rate = 0.0;      // Hz
  double duration = 0.0;  // s
  bool rotational = false;
  double friction = 0.0;
  double contact_stiffness = 0.0;  // N/m
  // Prepare times, s.
  double discretize_seconds = 0.0;
  double generate_seconds = 0.0;
  double analyze_seconds = 0.0;
  double prepare_seconds = 0.0;  // until every table was whole
  // Until the scene was ready to touch (a progressive prepare's ready steps; a whole prepare's
  // total).
  double ready_seconds = 0.0;
  int inner_rows = 0, inner_columns = 0, outer_rows = 0, outer_columns = 0;
  // The tilt the device holds the part at (Device::held_tilt), rad, 0: aligned; and how far the
  // tilted part's leading edge reaches past its leading end's centre, r sin(tilt), m.
  double held_tilt = 0.0;
  double leading_edge_lead = 0.0;
  // What the device reported after the run (Device::report); empty: nothing.
  DeviceReport device_report;
  // Measured parts: file, kind, whether each meets its drawing; null: none measured.
  nlohmann::json measured_parts;
};

struct OutputPaths {
  std::filesystem::path trace;      // empty when not written
  std::filesystem::path summary;    // empty when not written
  std::filesystem::path recording;  // empty when not written
};

// The device stream of a run, to be written as DIR/recording.csv.
struct RecordingOutput {
  RecordingInfo info;
  const std::vector<RecordedSample>* samples = nullptr;  // null: no recording
};

// Header of trace.csv, the output contract's columns first. fy is the axial resistance (the
// paper's y, along the mating axis), fx and fz the radial components; all on the moving part, in
// physical newtons. The dev_* columns at the end are what the safety chain sent to the device
// (device newtons: scaled, coupled, limited).
FITFEEL_API std::string TraceHeader();
// The same with a column per feature of a several-feature scene after the others:
// axial_<feature>_N, each feature's axial force (TickRecord::feature_axial).
FITFEEL_API std::string TraceHeader(const std::vector<std::string>& features, bool screw = false);
// One row of trace.csv (no newline). Numbers in their shortest exact decimal form.
FITFEEL_API std::string TraceRow(const TickRecord& record);
// The same row appended to `out` (no newline): no allocation once `out` has room.
FITFEEL_API void AppendTraceRow(std::string* out, const TickRecord& record);
// The same with `features` per-feature columns (TraceHeader(features)).
// A screw scene (`screw`) appends its joint's columns: preload_N, torque_Nm (turning the part
// against the contact), thread_torque_Nm and head_torque_Nm (its shares at the flanks and at the
// bearing face) and seated (1 once the bearing face has met).
FITFEEL_API void AppendTraceRow(std::string* out, const TickRecord& record, int features,
                                bool screw = false);

// Running mean, minimum and maximum of a sample.
struct RunningSummary {
  double sum = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  std::uint64_t count = 0;
  void Add(double v) {
    sum += v;
    min = std::min(min, v);
    max = std::max(max, v);
    ++count;
  }
  nlohmann::json ToJson() const {
    if (count == 0) return {{"mean", nullptr}, {"min", nullptr}, {"max", nullptr}};
    return {{"mean", sum / static_cast<double>(count)}, {"min", min}, {"max", max}};
  }
};

// summary.json's statistics gathered one tick at a time, so that a streamed run never holds its
// trace: Add every record in order, then Make.
class FITFEEL_API SummaryBuilder {
 public:
  void Add(const TickRecord& record);
  nlohmann::json Make(const RunInfo& info, const RunStats& stats) const;

 private:
  RunningSummary axial_, fy_, radial_, torque_, depth_;
  // What the safety chain delivered to the device (its force's magnitude), constrained ticks.
  RunningSummary delivered_;
  // A several-feature scene: each feature's axial force, and the torque about the axis and the
  // twist (every constrained tick).
  std::array<RunningSummary, kMaxJointFeatures> feature_axial_;
  int features_ = 0;
  RunningSummary axis_torque_, twist_;
  // A screw: its last constrained tick and its peaks.
  ScrewOutput screw_last_;
  double screw_angle_ = 0.0;
  RunningSummary screw_torque_, screw_preload_;
  double screw_rundown_torque_ = 0.0;  // the largest before the bearing face met, N*m
  std::uint64_t interference_ticks_ = 0;
  // The mating depth of the first constrained tick whose assembly space was empty or that a
  // compliant holder's two-point couple acted on, m; NaN: none.
  double first_interference_depth_ = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t yielding_ticks_ = 0;
  // Ticks whose contact was held at a progressive prepare's frontier (ContactState::held_depth),
  // the longest run of them in a row, and the deepest past the frontier, m.
  std::uint64_t held_ticks_ = 0, held_stretch_ = 0, held_longest_ = 0;
  double held_deepest_ = 0.0;
  TickRecord worst_;  // the tick with the largest elastic-limit utilisation
  bool has_worst_ = false;
};

// summary.json's content. Resistance statistics are taken over the ticks of the constrained stage:
// axial_resistance_N over |fy|, radial_resistance_N over sqrt(fx^2 + fz^2) (the paper's F_r),
// and for a rotational surface torque_Nm over |torque|; null when no tick was constrained. The
// `safety` object reports the chain: force scale, coupling and gains, faults, saturated ticks,
// energy created.
FITFEEL_API nlohmann::json MakeSummary(const RunInfo& info, const std::vector<TickRecord>& trace,
                                       const RunStats& stats);

// Writes DIR/trace.csv, DIR/summary.json and DIR/recording.csv (those asked for; the recording
// with WriteRecording's format), creating DIR if needed. Every file
// is written under a temporary name in DIR and renamed into place only once all are complete; on
// any failure the temporaries, the files renamed so far and a DIR this call created are removed
// and UserError is thrown, so a failed run leaves no file behind.
FITFEEL_API OutputPaths WriteOutputs(const std::filesystem::path& dir, const RunInfo& info,
                                     const std::vector<TickRecord>& trace, const RunStats& stats,
                                     bool write_trace = true, bool write_summary = true,
                                     const RecordingOutput& recording = {});

}  // namespace fitfeel
