#include "framework/runtime/run.h"

#include "framework/model/measured_surface.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/quantity.h"
#include "framework/model/measured_surface.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/trace_stream.h"

namespace fitfeel {
namespace {

// Stops the device however the run ends.
struct DeviceRun {
  explicit DeviceRun(Device& d, double period) : device(d) { device.Start(period); }
  ~DeviceRun() { device.Stop(); }
  DeviceRun(const DeviceRun&) = delete;
  DeviceRun& operator=(const DeviceRun&) = delete;
  Device& device;
};

std::string FormatStiffness(double n_per_m) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.3g N/mm", n_per_m * 1e-3);
  return buffer;
}

// For each measured part: its file and whether it meets its drawing, by the surface type's own
// metrology (the one that checks generated parts). Null when no part is measured.
nlohmann::json MeasuredPartsReport(const Scene& scene, const PreparedScene& prepared) {
  nlohmann::json report;
  for (const auto& [part, sms] : {std::pair{&scene.inner, prepared.inner_sms.get()},
                                  std::pair{&scene.outer, prepared.outer_sms.get()}}) {
    if (!part->measured) continue;
    nlohmann::json entry = {{"file", part->measured->file.string()},
                            {"kind", MeasurementKindName(part->measured->kind)}};
    try {
      nlohmann::json checks = nlohmann::json::array();
      bool meets = true;
      for (const CharacteristicCheck& c : scene.surface->EvaluateCharacteristics(*part, *sms)) {
        // The conformance suite's allowance: 0.1 nm of evaluation rounding.
        const bool pass = c.value >= c.lower - 1e-10 && c.value <= c.upper + 1e-10;
        meets = meets && pass;
        checks.push_back({{"name", c.name},
                          {"value_um", c.value * 1e6},
                          {"lower_um", c.lower * 1e6},
                          {"upper_um", c.upper * 1e6},
                          {"pass", pass}});
      }
      entry["meets_drawing"] = meets;
      entry["characteristics"] = checks;
    } catch (const UnsupportedError& e) {
      entry["meets_drawing"] = nullptr;
      entry["not_evaluated"] = e.what();
    }
    report[part->name] = entry;
  }
  return report;
}

}  // namespace

RunInfo MakeRunInfo(const Scene& scene, const PreparedScene& prepared) {
  RunInfo info;
  info.scenario = scene.name;
  info.scenario_file = scene.file;
  info.seed = scene.run.seed;
  info.surface = scene.surface_id;
  info.law = scene.model.law;
  info.device = scene.device_id;
  info.clock = scene.run.clock == ClockMode::kRealTime ? "realtime" : "virtual";
  info.rate = scene.run.rate;
  info.duration = scene.run.duration;
  info.rotational = prepared.rotational;
  for (const MatingFeature& feature : scene.features) info.features.push_back(feature.name);
  info.screw = IsScrewScene(scene);
  info.friction = scene.model.friction;
  info.contact_stiffness = scene.model.contact_stiffness;
  info.discretize_seconds = prepared.discretize_seconds;
  info.generate_seconds = prepared.generate_seconds;
  info.analyze_seconds = prepared.analyze_seconds;
  info.prepare_seconds = prepared.total_seconds;
  info.ready_seconds = prepared.ready_seconds;
  info.inner_rows = prepared.inner_sms->grid.rows;
  info.inner_columns = prepared.inner_sms->grid.columns;
  info.outer_rows = prepared.outer_sms->grid.rows;
  info.outer_columns = prepared.outer_sms->grid.columns;
  info.measured_parts = MeasuredPartsReport(scene, prepared);
  if (const std::optional<Eigen::Vector2d> tilt =
          scene.device ? scene.device->held_tilt() : std::nullopt) {
    info.held_tilt = tilt->norm();
    info.leading_edge_lead = 0.5 * scene.inner.size.nominal * std::sin(info.held_tilt);
  }
  return info;
}

RunResult RunScene(Scene scene, const RunOptions& options) {
  if (options.seed) scene.run.seed = *options.seed;
  if (options.clock) scene.run.clock = *options.clock;
  if (!scene.device) {
    throw UserError("scene '" + scene.name + "' has no device '" + scene.device_id + "'");
  }

  const auto stopped = [&options] { return options.stop != nullptr && options.stop->load(); };
  // The scene's own device drives this run: the contact need not be tabulated past its reach, in
  // depth or in turn.
  // In real time the ticks start once the scene is ready to touch, the rest prepared on a worker
  // thread ahead of the device; virtual time has no deadline to meet, and its trace is the same
  // bits either way, so the rest is prepared before the first tick, on every prepare thread.
  ProgressiveSettings progressive;
  progressive.worker =
      scene.run.clock == ClockMode::kRealTime || scene.device->clock_owner() == ClockOwner::kDevice;
  progressive.pace = options.prepare_pace;
  PreparedScene prepared = PrepareProgressive(scene, progressive, options.shared,
                                              scene.device->reach(scene.run.duration),
                                              scene.device->angular_reach(scene.run.duration));
  if (!progressive.worker) prepared.FinishPreparing();
  if (stopped()) throw Interrupted("while preparing the scene; no outputs written");
  if (options.prepared) options.prepared(prepared);
  return RunPreparedScene(scene, prepared, options);
}

RunResult RunPreparedScene(const Scene& scene, PreparedScene& prepared,
                           const RunOptions& options) {
  if (!scene.device) {
    throw UserError("scene '" + scene.name + "' has no device '" + scene.device_id + "'");
  }
  const auto stopped = [&options] { return options.stop != nullptr && options.stop->load(); };
  RunResult result;
  RunInfo& info = result.info;
  info = MakeRunInfo(scene, prepared);

  SchedulerSettings settings = SceneSchedulerSettings(scene);
  {
    DeviceRun device_run(*scene.device, 1.0 / scene.run.rate);
    // Hardware knows its limits only once started.
    const DeviceSpec spec = scene.device->spec();
    const SceneStages stages = MakeSceneStages(scene, prepared, spec);
    settings.safety = RuntimeSafetySettings(scene.safety, spec);
    settings.record = scene.run.write_recording;
    const bool coupled = settings.safety.coupling == CouplingMode::kSpringDamper;
    // The device meets k_free (the god object's spring, at most its limit), scaled.
    const double rendered = stages.positioning->options().free_stiffness;
    if (!coupled && std::isfinite(spec.max_stiffness) &&
        rendered * settings.safety.force_scale > spec.max_stiffness) {
      result.notes.push_back("note: stiffness " + FormatStiffness(rendered) + " scaled by " +
                             std::to_string(settings.safety.force_scale) +
                             " exceeds what the device '" + scene.device_id + "' renders stably (" +
                             FormatStiffness(spec.max_stiffness) + " at " +
                             std::to_string(std::lround(settings.rate)) +
                             " Hz) with direct rendering: expect chatter; the safety section's "
                             "coupling: spring_damper renders it through a virtual coupling");
    }
    // The outputs stream to disk while the run goes (temporaries renamed at the end): memory
    // does not grow with the duration, and a failed run leaves nothing.
    StreamOutputs outputs;
    outputs.dir = options.out_dir;
    outputs.trace = scene.run.write_trace;
    outputs.summary = scene.run.write_summary;
    if (scene.run.write_recording) outputs.recording = RecordingInfo{spec.model};
    for (const MatingFeature& feature : scene.features) outputs.features.push_back(feature.name);
    outputs.screw = IsScrewScene(scene);
    // A run of fewer ticks than the ring's default holds needs no more rows than it has ticks:
    // the ring then never fills, whatever the clock, and a short run (a study's pair) does not
    // build and touch the default's megabytes. The scheduler refuses a duration without a tick.
    const double ticks = std::round(settings.duration * settings.rate);
    const std::size_t capacity =
        ticks >= 1.0 && ticks < static_cast<double>(TraceStream::kDefaultCapacity)
            ? static_cast<std::size_t>(ticks)
            : TraceStream::kDefaultCapacity;
    TraceStream stream(outputs, options.observer, capacity);
    settings.stream = &stream.ring();
    settings.stop = options.stop;
    Scheduler scheduler(*scene.device, *stages.positioning, *stages.constrained, settings);
    scheduler.set_observer(options.observer);
    if (options.watch) options.watch(&scheduler);
    try {
      scheduler.Run();
    } catch (...) {
      if (options.watch) options.watch(nullptr);
      throw;
    }
    if (options.watch) options.watch(nullptr);
    if (stopped()) {
      // The stream's destructor removes the temporaries (and a folder it created).
      throw Interrupted("after " + std::to_string(scheduler.ticks_done()) + " of " +
                        std::to_string(scheduler.planned_ticks()) + " ticks; no outputs written");
    }
    // The rest of the tables (what the worker had left when the ticks ended), so that the
    // summary states the whole prepare's time; the worker's error, if any, fails the run here.
    prepared.FinishPreparing();
    info.analyze_seconds = prepared.analyze_seconds;
    info.prepare_seconds = prepared.total_seconds;
    result.stats = scheduler.stats();
    result.final_pose = scheduler.last_output().pose;
    result.final_stage = scheduler.last_output().stage;
    info.device_report = scene.device->report();
    if (info.device_report.IsTrue("stopped_on_faults")) {
      result.notes.push_back("warning: the device '" + scene.device_id +
                             "' kept faulting and the run was stopped early; see device_report "
                             "in summary.json");
    }
    if (!result.stats.realtime_note.empty() &&
        result.stats.realtime_note.find("not permitted") != std::string::npos) {
      result.notes.push_back(result.stats.realtime_note);
    }
    if (result.stats.guard_faults > 0) {
      result.notes.push_back("warning: " + std::to_string(result.stats.guard_faults) +
                             " ticks produced a non-finite wrench; zero was sent instead");
    }
    const SafetyReport& safety = result.stats.safety;
    if (safety.non_finite_faults > 0) {
      result.notes.push_back("warning: the safety chain sent zero force on " +
                             std::to_string(safety.non_finite_faults) +
                             " ticks whose device state or wrench was not finite");
    }
    if (result.stats.device_faults > 0) {
      result.notes.push_back("warning: the device '" + scene.device_id + "' reported " +
                             std::to_string(result.stats.device_faults) +
                             " states that were not finite or beyond physical bounds; the last "
                             "sane state was held and zero force sent (trace.csv: device_fault)");
    }
    if (result.stats.dropped_rows > 0) {
      result.notes.push_back("warning: the output writer fell behind the real-time loop and " +
                             std::to_string(result.stats.dropped_rows) +
                             " ticks are missing from the outputs (summary.json: dropped_rows)");
    }
    result.paths = stream.Finish(info, result.stats, &result.summary);
    if (options.observer != nullptr) options.observer->OnRunEnd();
  }
  return result;
}

}  // namespace fitfeel
