// fitfeel run [FILE] [--out DIR] [--seed N] [--realtime|--virtual]
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "framework/cli/commands.h"
#include "framework/cli/interrupts.h"
#include "framework/cli/strict_options.h"
#include "framework/core/build_info.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/path_check.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/run.h"
#include "framework/runtime/sequence_run.h"
#include "framework/scenario/scene.h"
#include "framework/scenario/sequence.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

struct RunArgs {
  std::string file;
  std::string out;
  std::optional<std::uint64_t> seed;
  bool realtime = false;
  bool virtual_clock = false;
  bool allow_large = false;
};

// A progress line on a terminal for runs longer than a second, drawn from a thread of its own:
// the tick loop only publishes its tick count.
class Progress {
 public:
  void Start(const Scheduler* scheduler) {
    if (!isatty(STDERR_FILENO)) return;
    thread_ = std::thread([this, scheduler] { Draw(scheduler); });
  }
  void Stop() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
    if (drawn_) std::fprintf(stderr, "\r\033[K");
  }
  ~Progress() { Stop(); }

 private:
  void Draw(const Scheduler* scheduler) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stop_; })) return;
    const auto planned = scheduler->planned_ticks();
    do {
      const auto done = scheduler->ticks_done();
      std::fprintf(stderr, "\r  running: %llu / %llu ticks (%.0f %%)",
                   static_cast<unsigned long long>(done), static_cast<unsigned long long>(planned),
                   100.0 * static_cast<double>(done) / static_cast<double>(planned));
      std::fflush(stderr);
      drawn_ = true;
    } while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stop_; }));
  }

  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool drawn_ = false;
};

std::string Stat(const nlohmann::json& s, const char* unit) {
  if (s["mean"].is_null()) return "none (no constrained tick)";
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "mean %.4g %s, min %.4g %s, max %.4g %s",
                s["mean"].get<double>(), unit, s["min"].get<double>(), unit, s["max"].get<double>(),
                unit);
  return buffer;
}

void PrintSummary(const RunResult& r) {
  const auto& j = r.summary;
  const auto& s = r.stats;
  std::printf("fitfeel run: %s (%s)\n", r.info.scenario.c_str(),
              r.info.scenario_file.string().c_str());
  std::printf("  seed %llu, law %s, device %s, %s clock\n",
              static_cast<unsigned long long>(r.info.seed), r.info.law.c_str(),
              r.info.device.c_str(), r.info.clock.c_str());
  std::printf("  prepare %.3f s (grid %dx%d inner, %dx%d outer)\n", r.info.prepare_seconds,
              r.info.inner_rows, r.info.inner_columns, r.info.outer_rows, r.info.outer_columns);
  std::printf("  %llu ticks at %g Hz in %.3f s, %llu constrained, deadline misses %llu\n",
              static_cast<unsigned long long>(s.ticks), r.info.rate, s.wall_seconds,
              static_cast<unsigned long long>(j["constrained_ticks"].get<std::uint64_t>()),
              static_cast<unsigned long long>(s.deadline_misses));
  std::printf("  tick compute  p50 %.2f us, p99 %.2f us, max %.2f us\n", s.compute_us.p50,
              s.compute_us.p99, s.compute_us.max);
  if (s.realtime) {
    std::printf("  period jitter p50 %.1f us, p99 %.1f us, max %.1f us (%s)\n", s.jitter_us.p50,
                s.jitter_us.p99, s.jitter_us.max, s.realtime_note.c_str());
  }
  std::printf("  axial resistance  %s\n", Stat(j["axial_resistance_N"], "N").c_str());
  std::printf("  radial resistance %s\n", Stat(j["radial_resistance_N"], "N").c_str());
  if (j.contains("torque_Nm")) {
    std::printf("  resistance torque %s\n", Stat(j["torque_Nm"], "N*m").c_str());
  }
  const SafetyReport& safety = s.safety;
  const bool coupled = safety.coupling == CouplingMode::kSpringDamper;
  const ForceMapping& map = safety.mapping;
  char mapping[160];
  if (map.kind() == ForceMappingKind::kPerceptual) {
    std::snprintf(mapping, sizeof mapping,
                  "perceptual map (knee %g N, exponent %.4g, %g N -> %g N)", map.knee(),
                  map.exponent(), map.scene_top(), map.device_top());
  } else {
    std::snprintf(mapping, sizeof mapping, "scale %g device N/N", safety.force_scale);
  }
  std::printf(
      "  safety  %s, %s, faults %llu, saturated ticks %llu, energy "
      "created %.3g J\n",
      mapping, coupled ? "virtual coupling" : "direct",
      static_cast<unsigned long long>(safety.non_finite_faults),
      static_cast<unsigned long long>(safety.peak_limited_ticks + safety.continuous_limited_ticks),
      safety.energy_created);
  if (coupled) {
    std::printf("          coupling K_c %g N/m, B_c %g N*s/m\n", safety.coupling_gains.stiffness,
                safety.coupling_gains.damping);
  }
  for (const auto& note : r.notes) std::printf("  %s\n", note.c_str());
  if (!r.paths.trace.empty()) std::printf("  trace   %s\n", r.paths.trace.string().c_str());
  if (!r.paths.summary.empty()) std::printf("  summary %s\n", r.paths.summary.string().c_str());
  if (!r.paths.recording.empty()) {
    std::printf("  recording %s\n", r.paths.recording.string().c_str());
  }
}

// What a run of the scenario `name` takes from the command line: its folder (checked), seed and
// clock, the progress line and the interrupt's cooperation.
RunOptions CommandRunOptions(const RunArgs& args, const std::string& name, Progress* progress,
                             InterruptScope* interrupt) {
  RunOptions options;
  options.out_dir = args.out.empty() ? fs::path("out") / name : fs::path(args.out);
  CheckOutputFolder("--out", options.out_dir);
  options.seed = args.seed;
  if (args.realtime) options.clock = ClockMode::kRealTime;
  if (args.virtual_clock) options.clock = ClockMode::kVirtual;
  options.watch = [progress](const Scheduler* scheduler) {
    if (scheduler) {
      progress->Start(scheduler);
    } else {
      progress->Stop();
    }
  };
  options.stop = &InterruptFlag();
  options.prepared = [interrupt](const PreparedScene&) { interrupt->Cooperate(); };
  SweepStaleTemporaries(options.out_dir);
  return options;
}

// A sequence: its steps in order, each printed as a run is, then the sequence's summary.
void RunSteps(const RunArgs& args, const fs::path& file, const PluginRegistry& registry,
              const LoadOptions& load, InterruptScope& interrupt) {
  const Sequence sequence = LoadSequence(file, registry, load);
  Progress progress;
  const RunOptions options = CommandRunOptions(args, sequence.name, &progress, &interrupt);
  for (const SequenceStep& step : sequence.steps) {
    SweepStaleTemporaries(options.out_dir / step.scene.name);
  }
  const SequenceResult result = RunSequence(sequence, options);
  std::printf("fitfeel run: sequence %s (%s), %zu steps\n", sequence.name.c_str(),
              file.string().c_str(), result.steps.size());
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    std::printf("\nstep %zu: %s\n", k + 1, sequence.steps[k].scene.name.c_str());
    PrintSummary(result.steps[k]);
  }
  if (!result.summary.empty()) std::printf("\nsummary %s\n", result.summary.string().c_str());
}

void Run(const RunArgs& args) {
  // Until the scene is prepared nothing is written and SIGINT or SIGTERM ends the process at once;
  // from then on the run stops at the next tick boundary and removes its temporaries: an
  // interrupted run writes nothing (a trace cut short would pass for a run of another length).
  InterruptScope interrupt("fitfeel run");
  const fs::path file = args.file.empty() ? FindDefaultScenario() : fs::path(args.file);
  if (!args.out.empty()) CheckOutputFolder("--out", args.out);
  PluginRegistry registry;
  registry.LoadAll();
  // Every check of the scenario happens here, before anything runs or any file is created.
  LoadOptions load;
  load.allow_large = args.allow_large;
  if (IsSequenceFile(file)) {
    RunSteps(args, file, registry, load, interrupt);
    return;
  }
  Scene scene = LoadScene(file, registry, load);
  Progress progress;
  const RunOptions options = CommandRunOptions(args, scene.name, &progress, &interrupt);
  const RunResult result = RunScene(std::move(scene), options);
  PrintSummary(result);
}

}  // namespace

std::filesystem::path FindShippedFile(const std::filesystem::path& relative) {
  // Whatever is there is taken (LoadScene says why it cannot be read, in the OS's words).
  if (WhyNotReadableFile(relative) != kDoesNotExist) return relative;
  if (relative.is_relative()) {
    if (const char* source = std::getenv("FITFEEL_SOURCE_DIR"); source && *source) {
      const fs::path there = fs::path(source) / relative;
      if (WhyNotReadableFile(there) != kDoesNotExist) return there;
    }
    if (!ShippedDataDir().empty()) {
      const fs::path shipped = fs::path(ShippedDataDir()) / relative;
      if (WhyNotReadableFile(shipped) != kDoesNotExist) return shipped;
    }
  }
  return fs::path();
}

std::filesystem::path FindDefaultScenario() {
  const fs::path found = FindShippedFile(kDefaultScenario);
  if (!found.empty()) return found;
  throw UserError("no scenario file given and the default '" + std::string(kDefaultScenario) +
                  "' was not found in the current folder, under FITFEEL_SOURCE_DIR" +
                  (ShippedDataDir().empty() ? std::string(" (this install ships no scenarios)")
                                            : " or in '" + ShippedDataDir() + "'") +
                  "; give a scenario file");
}

void AddRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand(
      "run",
      "Run a scenario: build the skin model shapes, drive the device at the scenario's rate and "
      "write DIR/trace.csv and DIR/summary.json (and DIR/recording.csv when run.outputs asks)");
  cmd->add_option("file", args->file,
                  std::string("scenario file (default: ") + kDefaultScenario +
                      ", looked up in the current folder, then in FITFEEL_SOURCE_DIR, then "
                      "among the shipped scenarios)");
  cmd->add_option("--out", args->out, "output folder (default: out/<scenario name>)");
  AddSeedOption(
      cmd, "--seed", [args](std::uint64_t seed) { args->seed = seed; },
      "seed of the scene's random generator (overrides run.seed; the same range)");
  cmd->add_flag("--allow-large", args->allow_large,
                "run a scene whose estimated preparation exceeds 1 GiB or 30 s, or whose trace "
                "and recording would exceed 4 GiB");
  auto* realtime = cmd->add_flag("--realtime", args->realtime,
                                 "real-time clock: absolute 1 kHz deadlines (overrides run.clock)");
  auto* virtual_clock = cmd->add_flag("--virtual", args->virtual_clock,
                                      "virtual clock: as fast as possible, deterministic");
  realtime->excludes(virtual_clock);
  cmd->callback([args] { Run(*args); });
}

}  // namespace fitfeel::cli
