#include "framework/runtime/outputs.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <system_error>
#include <utility>
#include <variant>

#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/core/os_reason.h"
#include "framework/core/temporary_files.h"
#include "framework/runtime/trace_columns.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

nlohmann::json ToJson(const Percentiles& p) {
  return {{"p50", p.p50}, {"p99", p.p99}, {"max", p.max}};
}

void WriteFile(const fs::path& path, const std::string& text) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  const int open_error = errno;
  if (!out) throw UserError("cannot create '" + path.string() + "': " + OsReason(open_error));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw UserError("cannot write '" + path.string() + "' (disk full?)");
}

}  // namespace

std::string TraceHeader() { return TraceHeader({}, false); }

std::string TraceHeader(const std::vector<std::string>& features, bool screw) {
  std::string header;
  for (const TraceColumn& column : TraceColumns(features, screw)) {
    if (!header.empty()) header += ',';
    header += column.name;
  }
  return header;
}

void AppendTraceRow(std::string* out, const TickRecord& r, int features, bool screw) {
  // The kinds of a screw scene's columns without features: the features' own are numbers.
  static const std::vector<TraceColumn> kinds = TraceColumns({}, true);
  static const int base = TraceColumnCount(0, false);
  features = std::clamp(features, 0, kMaxJointFeatures);
  std::array<double, kMaxJointFeatures + 64> values;
  const int count = TraceColumnCount(features, screw);
  TraceValues(r, features, screw, values.data());
  std::string& row = *out;
  for (int k = 0; k < count; ++k) {
    if (k > 0) row += ',';
    const bool feature = k >= base && k < base + features;
    const TraceColumnKind kind =
        feature ? TraceColumnKind::kNumber
                : kinds[static_cast<std::size_t>(k < base ? k : k - features)].kind;
    switch (kind) {
      case TraceColumnKind::kNumber:
        AppendShortestDecimal(&row, values[static_cast<std::size_t>(k)]);
        break;
      case TraceColumnKind::kFlag:
        row += values[static_cast<std::size_t>(k)] != 0.0 ? '1' : '0';
        break;
      case TraceColumnKind::kStage:
        row += ToString(r.stage);
        break;
    }
  }
}

std::string TraceRow(const TickRecord& r) {
  std::string row;
  row.reserve(256);
  AppendTraceRow(&row, r);
  return row;
}

void AppendTraceRow(std::string* out, const TickRecord& r) { AppendTraceRow(out, r, 0, false); }

void SummaryBuilder::Add(const TickRecord& r) {
  if (r.contact.held_depth > 0.0) {
    ++held_ticks_;
    held_longest_ = std::max(held_longest_, ++held_stretch_);
    held_deepest_ = std::max(held_deepest_, r.contact.held_depth);
  } else {
    held_stretch_ = 0;
  }
  if (r.stage != StageId::kConstrained) return;
  if (r.elastic.utilisation > 1.0) ++yielding_ticks_;
  if (r.elastic.utilisation > 0.0 &&
      (!has_worst_ || r.elastic.utilisation > worst_.elastic.utilisation)) {
    worst_ = r;
    has_worst_ = true;
  }
  axial_.Add(std::abs(r.wrench.force.y()));
  delivered_.Add(r.device_wrench.force.norm());
  fy_.Add(r.wrench.force.y());
  radial_.Add(std::hypot(r.wrench.force.x(), r.wrench.force.z()));
  torque_.Add(r.wrench.torque.norm());
  depth_.Add(r.pose.depth * 1e3);
  if (r.contact.interference) ++interference_ticks_;
  // A compliant holder's part meets two points where their couple first acts.
  if ((r.contact.interference || r.contact.couple_normal > 0.0) &&
      std::isnan(first_interference_depth_)) {
    first_interference_depth_ = r.pose.depth;
  }
  if (r.feature_count > 0) {
    features_ = r.feature_count;
    for (int i = 0; i < r.feature_count && i < kMaxJointFeatures; ++i) {
      feature_axial_[i].Add(std::abs(r.feature_axial[i]));
    }
    axis_torque_.Add(r.wrench.torque.y());
    twist_.Add(r.pose.angle);
  }
  if (r.screw.active) {
    screw_last_ = r.screw;
    screw_angle_ = r.pose.angle;
    screw_torque_.Add(r.screw.torque);
    screw_preload_.Add(r.screw.preload);
    if (!r.screw.seated) screw_rundown_torque_ = std::max(screw_rundown_torque_, r.screw.torque);
  }
}

nlohmann::json MakeSummary(const RunInfo& info, const std::vector<TickRecord>& trace,
                           const RunStats& stats) {
  SummaryBuilder builder;
  for (const auto& r : trace) builder.Add(r);
  return builder.Make(info, stats);
}

nlohmann::json SummaryBuilder::Make(const RunInfo& info, const RunStats& stats) const {
  const RunningSummary &axial = axial_, &fy = fy_, &radial = radial_, &torque = torque_,
                       &depth = depth_;
  const std::uint64_t interference_ticks = interference_ticks_;
  const std::uint64_t yielding_ticks = yielding_ticks_;
  const TickRecord* worst = has_worst_ ? &worst_ : nullptr;
  nlohmann::json j;
  j["scenario"] = info.scenario;
  j["scenario_file"] = info.scenario_file.string();
  j["seed"] = info.seed;
  j["surface"] = info.surface;
  j["law"] = info.law;
  j["device"] = info.device;
  j["clock"] = info.clock;
  j["rate_Hz"] = info.rate;
  j["duration_s"] = info.duration;
  j["friction"] = info.friction;
  j["contact_stiffness_N_per_m"] = info.contact_stiffness;
  j["ticks"] = stats.ticks;
  j["planned_ticks"] = stats.planned_ticks;
  j["constrained_ticks"] = axial.count;
  j["interference_ticks"] = interference_ticks;
  // A part held tilted in a bore stops fitting where it touches at two points, the entrance's
  // edge on one side and its own leading edge on the other (Whitney 1982): there its assembly
  // space empties. Reported as the leading edge's depth past the entrance.
  j["held_tilt_deg"] = info.held_tilt * 180.0 / std::numbers::pi;
  j["two_point_contact_depth_mm"] =
      info.held_tilt > 0.0 && std::isfinite(first_interference_depth_)
          ? nlohmann::json((first_interference_depth_ + info.leading_edge_lead) * 1e3)
          : nlohmann::json(nullptr);
  j["deadline_misses"] = stats.deadline_misses;
  j["overruns"] = stats.overruns;
  j["guard_faults"] = stats.guard_faults;
  j["device_faults"] = stats.device_faults;
  j["dropped_rows"] = stats.dropped_rows;
  // A progressive prepare that the device outran: the ticks that felt the contact held at the
  // prepared frontier, their longest stretch and how far past the frontier the part went.
  j["held_for_prepare"] = {
      {"ticks", held_ticks_},
      {"longest_s", info.rate > 0.0 ? static_cast<double>(held_longest_) / info.rate : 0.0},
      {"deepest_mm", held_deepest_ * 1e3}};
  j["tick_us"] = ToJson(stats.compute_us);
  j["contact_evaluations"] = ToJson(stats.contact_evaluations);
  if (stats.realtime) {
    j["period_jitter_us"] = ToJson(stats.jitter_us);
    j["wake_lateness_us"] = ToJson(stats.lateness_us);
    j["realtime_note"] = stats.realtime_note;
  }
  j["wall_s"] = stats.wall_seconds;
  j["axial_resistance_N"] = axial.ToJson();
  j["fy_N"] = fy.ToJson();
  j["radial_resistance_N"] = radial.ToJson();
  // In device newtons: the scene's forces after the safety chain's scale, mapping and limits.
  j["delivered_force_N"] = delivered_.ToJson();
  if (info.rotational) j["torque_Nm"] = torque.ToJson();
  if (!info.features.empty()) {
    // Each feature's share of the axial resistance (|fy| of its own wrench), by name.
    nlohmann::json features = nlohmann::json::object();
    for (std::size_t i = 0; i < info.features.size() && i < feature_axial_.size(); ++i) {
      features[info.features[i]] = {{"axial_resistance_N", feature_axial_[i].ToJson()}};
    }
    j["features"] = features;
    j["axis_torque_Nm"] = axis_torque_.ToJson();
    j["twist_rad"] = twist_.ToJson();
  }
  if (info.screw) {
    // The joint at the end of the run, and how far the part turned once its face met.
    const ScrewOutput& s = screw_last_;
    j["thread"] = {
        {"preload_N", s.preload},
        {"torque_Nm", s.torque},
        {"thread_torque_Nm", s.thread_torque},
        {"head_torque_Nm", s.head_torque},
        {"seated", s.seated},
        // How the run-down went: the face met ("seated"), the wrench's target reached before it
        // (a cross-threaded or jammed start: "jammed"), or neither by the end ("running").
        {"start", s.seated ? "seated" : (s.stopped ? "jammed" : "running")},
        {"rundown_torque_Nm", screw_rundown_torque_},
        {"turn_after_snug_deg",
         s.seated ? (screw_angle_ - s.snug_angle) * 180.0 / std::numbers::pi : 0.0},
        {"target_reached", s.stopped},
        {"torque_Nm_over_run", screw_torque_.ToJson()},
        {"preload_N_over_run", screw_preload_.ToJson()},
    };
  }
  j["depth_mm"] = depth.ToJson();
  // Where and by how much the contact's stresses came closest to (or passed) the yield strength.
  nlohmann::json elastic = {{"yielding_ticks", yielding_ticks}};
  if (worst != nullptr) {
    const double u = worst->elastic.utilisation;
    elastic["max_utilisation"] = u;
    elastic["part"] = worst->elastic.part == 2 ? "inner" : "outer";
    elastic["at_t_s"] = worst->time;
    elastic["at_depth_mm"] = worst->pose.depth * 1e3;
    elastic["at_angle_rad"] = worst->pose.angle;
    elastic["excess_percent"] = u > 1.0 ? (u - 1.0) * 100.0 : 0.0;
  } else {
    elastic["max_utilisation"] = nullptr;  // not checked: no law check or no yield strength
  }
  j["elastic_limit"] = elastic;
  const SafetyReport& safety = stats.safety;
  nlohmann::json coupling = {
      {"mode", safety.coupling == CouplingMode::kSpringDamper ? "spring_damper" : "direct"}};
  if (safety.coupling == CouplingMode::kSpringDamper) {
    coupling["stiffness_N_per_m"] = safety.coupling_gains.stiffness;
    coupling["damping_Ns_per_m"] = safety.coupling_gains.damping;
  }
  // JSON has no infinity: an unlimited device's limits are null.
  auto limit = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  const ForceMapping& map = safety.mapping;
  nlohmann::json mapping = {
      {"kind", map.kind() == ForceMappingKind::kPerceptual ? "perceptual" : "linear"}};
  if (map.kind() == ForceMappingKind::kPerceptual) {
    mapping["knee_N"] = map.knee();
    mapping["exponent"] = map.exponent();
    mapping["scene_top_N"] = map.scene_top();
    mapping["device_top_N"] = map.device_top();
  } else {
    mapping["scale"] = map.scale();
  }
  j["safety"] = {{"device_model", safety.device_model},
                 {"force_scale", safety.force_scale},
                 {"force_mapping", mapping},
                 {"coupling", coupling},
                 {"peak_force_limit_N", limit(safety.peak_force_limit)},
                 {"continuous_force_limit_N", limit(safety.continuous_force_limit)},
                 {"faults", safety.non_finite_faults},
                 {"saturated_ticks", safety.peak_limited_ticks + safety.continuous_limited_ticks},
                 {"peak_limited_ticks", safety.peak_limited_ticks},
                 {"continuous_limited_ticks", safety.continuous_limited_ticks},
                 {"passivity_controller_ticks", safety.passivity_controller_ticks},
                 {"max_physical_force_N", safety.max_physical_force},
                 {"max_delivered_force_N", safety.max_delivered_force},
                 {"energy_absorbed_J", safety.energy},
                 {"energy_created_J", safety.energy_created},
                 {"controller_energy_J", safety.controller_energy}};
  if (!info.device_report.empty()) {
    nlohmann::json report = nlohmann::json::object();
    for (const DeviceReport::Entry& e : info.device_report.entries()) {
      std::visit([&](const auto& value) { report[e.key] = value; }, e.value);
    }
    j["device_report"] = std::move(report);
  }
  if (!info.measured_parts.is_null()) j["measured_parts"] = info.measured_parts;
  j["prepare_s"] = {{"discretize", info.discretize_seconds},
                    {"generate", info.generate_seconds},
                    {"analyze", info.analyze_seconds},
                    {"total", info.prepare_seconds}};
  j["ready_to_touch_ms"] = info.ready_seconds * 1e3;
  j["grid"] = {{"inner", {{"rows", info.inner_rows}, {"columns", info.inner_columns}}},
               {"outer", {{"rows", info.outer_rows}, {"columns", info.outer_columns}}}};
  return j;
}

OutputPaths WriteOutputs(const fs::path& dir, const RunInfo& info,
                         const std::vector<TickRecord>& trace, const RunStats& stats,
                         bool write_trace, bool write_summary, const RecordingOutput& recording) {
  OutputPaths paths;
  const bool write_recording = recording.samples != nullptr;
  if (!write_trace && !write_summary && !write_recording) return paths;
  std::error_code ec;
  const bool created_dir = !fs::exists(dir, ec);
  if (created_dir && !fs::create_directories(dir, ec) && ec) {
    throw UserError("cannot create output folder '" + dir.string() + "': " + ec.message());
  }
  if (!fs::is_directory(dir, ec)) {
    throw UserError("output path '" + dir.string() + "' is not a folder");
  }

  struct Pending {
    fs::path temporary;
    fs::path final;
  };
  std::vector<Pending> pending;
  std::vector<fs::path> renamed;
  try {
    if (write_trace) {
      std::string text = TraceHeader() + "\n";
      text.reserve(text.size() + trace.size() * 200);
      for (const auto& r : trace) {
        text += TraceRow(r);
        text += '\n';
      }
      pending.push_back({TemporaryPathFor(dir / "trace.csv"), dir / "trace.csv"});
      WriteFile(pending.back().temporary, text);
      paths.trace = pending.back().final;
    }
    if (write_summary) {
      const std::string text = MakeSummary(info, trace, stats).dump(2) + "\n";
      pending.push_back({TemporaryPathFor(dir / "summary.json"), dir / "summary.json"});
      WriteFile(pending.back().temporary, text);
      paths.summary = pending.back().final;
    }
    if (write_recording) {
      pending.push_back({TemporaryPathFor(dir / "recording.csv"), dir / "recording.csv"});
      // WriteRecording checks every sample and writes atomically itself; the rename below joins
      // it to the others.
      WriteRecording(pending.back().temporary, recording.info, *recording.samples);
      paths.recording = pending.back().final;
    }
    for (const auto& p : pending) {
      fs::rename(p.temporary, p.final, ec);
      if (ec) {
        throw UserError("cannot move '" + p.temporary.string() + "' to '" + p.final.string() +
                        "': " + ec.message());
      }
      renamed.push_back(p.final);
    }
  } catch (...) {
    for (const auto& p : pending) fs::remove(p.temporary, ec);
    for (const auto& f : renamed) fs::remove(f, ec);
    if (created_dir) fs::remove(dir, ec);  // only removes it if empty
    throw;
  }
  return paths;
}

}  // namespace fitfeel
