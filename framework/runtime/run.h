#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/export.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scheduler.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

struct RunOptions {
  std::filesystem::path out_dir;      // where trace.csv and summary.json go; empty: nowhere
  std::optional<ClockMode> clock;     // overrides run.clock
  std::optional<std::uint64_t> seed;  // overrides run.seed
  // Called with the scheduler just before its loop starts and with null once it has ended, on
  // the calling thread; the scheduler's ticks_done() may be polled from another thread between.
  std::function<void(const Scheduler*)> watch;
  // Called once the scene is prepared, before the device starts (a study reads the drawn parts).
  std::function<void(const PreparedScene&)> prepared;
  // Watches every tick and the finished trace (a live viewer); borrowed, may be null.
  TickObserver* observer = nullptr;
  // Borrowed, may be null: once set (an interrupt, InterruptFlag) the run ends at the next tick
  // boundary, its temporaries are removed and RunScene throws Interrupted ("after N of M ticks;
  // no outputs written"). An interrupted run writes nothing: a trace cut short would read as a
  // complete run of another duration.
  const std::atomic<bool>* stop = nullptr;
  // Borrowed, may be null: what the prepare takes from and leaves for the prepares of other runs
  // of the same scene (a study's pairs; SharedPrepare). The run's results do not depend on it.
  SharedPrepare* shared = nullptr;
  // Test hook (may be empty): a run in real time prepares its tables progressively on a worker
  // thread (ProgressiveSettings::pace), which asks this before each step and waits while it
  // answers false.
  std::function<bool()> prepare_pace;
};

struct RunResult {
  RunInfo info;
  RunStats stats;
  OutputPaths paths;
  nlohmann::json summary;
  std::vector<std::string> notes;  // one line each, for the user (stiffness beyond the device...)
  // Where the last tick left the moving part (a sequence's next step seats it there), and in
  // which stage.
  MatingPose final_pose;
  StageId final_stage = StageId::kPositioning;
};

// A whole run of a loaded scene: the prepare, the two stages, the device started at run.rate, the
// scheduler, and the outputs written atomically. The prepare is progressive (PrepareProgressive):
// the run starts once the scene is ready to touch; in virtual time the rest is prepared before the
// first tick (the same trace bit for bit as a whole prepare's), in real time on a worker thread
// while the ticks run (a tick past its frontier feels the contact held there; summary.json's
// held_for_prepare), and finished before the outputs are written. Throws UserError/UnsupportedError
// before any file is created when the scene cannot run, Interrupted when options.stop was set (no
// file left).
FITFEEL_API RunResult RunScene(Scene scene, const RunOptions& options);

// The run of a scene already prepared (Prepare or PrepareProgressive with the device's reach,
// or +inf): the part of RunScene after its preparation, for a caller that runs one prepared scene
// more than once (a live view's passes). `options.seed`, `clock` and `prepared` are not read: the
// scene's own run settings apply, and `prepared` must be this scene's. A progressive prepare's
// rest is finished after the ticks (FinishPreparing), so the next run of it is whole.
FITFEEL_API RunResult RunPreparedScene(const Scene& scene, PreparedScene& prepared,
                                       const RunOptions& options);

// What summary.json says of a prepared scene before its run (name, law, rates, prepare times,
// grids, measured parts); the device report is added after the run.
FITFEEL_API RunInfo MakeRunInfo(const Scene& scene, const PreparedScene& prepared);

}  // namespace fitfeel
