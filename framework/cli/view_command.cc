// fitfeel view [FILE] [--port N] [--host H] [--trace DIR] [--realtime|--virtual] [--seed N]
// FILE may be a scene or a sequence (its steps shown one after another), DIR a finished run's
// folder or a finished sequence's.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/cli/interrupts.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/plot/run_record.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/run.h"
#include "framework/runtime/sequence_run.h"
#include "framework/scenario/scene.h"
#include "framework/scenario/sequence.h"
#include "framework/view/live_session.h"
#include "framework/view/sequence_view.h"
#include "framework/view/server.h"
#include "framework/view/tick_publisher.h"
#include "framework/view/view_model.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

struct ViewArgs {
  std::string file;
  std::string trace;
  std::string out;
  std::string host = "127.0.0.1";
  unsigned port = 8000;
  std::optional<std::uint64_t> seed;
  bool realtime = false;
  bool virtual_clock = false;
  double frame_rate = 60.0;
  int max_clients = 64;
  double exit_after = -1.0;
  bool wait = false;
  bool allow_large = false;
  bool edit = false;
  std::string compare;
};

// The constrained rows of a finished run as viewer samples. A several-feature scene's rows take
// the trace's torque, whose component about the axis its page shows; a one-feature scene's rows
// carry none (a rotational pair's finished run shows 0 N*m where its live run shows the torque).
std::vector<view::ViewSample> HistoryOf(const plot::ConstrainedTrace& t,
                                        const view::ViewModel& model) {
  std::vector<view::ViewSample> rows(t.t_s.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    view::ViewSample& s = rows[k];
    s.time = t.t_s[k];
    s.tick = k;
    s.depth = t.depth_mm[k] * 1e-3;
    if (!t.offset_x_um.empty()) {
      s.offset_x = t.offset_x_um[k] * 1e-6;
      s.offset_z = t.offset_z_um[k] * 1e-6;
    } else if (!t.x_mm.empty()) {
      s.offset_x = t.x_mm[k] * 1e-3;
      s.offset_z = t.z_mm[k] * 1e-3;
    }
    if (!t.angle_rad.empty()) s.angle = t.angle_rad[k];
    s.force[0] = t.fx_N[k];
    s.force[1] = t.fy_N[k];
    s.force[2] = t.fz_N[k];
    if (model.several_features() && !t.ty_Nm.empty()) {
      s.torque[0] = t.tx_Nm[k];
      s.torque[1] = t.ty_Nm[k];
      s.torque[2] = t.tz_Nm[k];
    }
    s.stage = 1;
    view::InOuterPartsFrame(&s, model.moving());
    model.FillContact(&s);
  }
  return rows;
}

void Serve(view::Server& server, const ViewArgs& args) {
  if (args.exit_after >= 0.0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(args.exit_after));
    std::printf("  served %llu state frames\n",
                static_cast<unsigned long long>(server.frames_sent()));
    std::fflush(stdout);
    server.Stop();
    return;
  }
  // Until the user interrupts (Ctrl-C): nothing is left to write, and the interrupt scope ends the
  // process at once with its line.
  for (;;) pause();
}

// A finished sequence's summary.json (DIR/summary.json with `steps`), or nothing for any other
// folder (LoadRun then reads it as a run's, and says what is wrong with it).
std::optional<nlohmann::json> SequenceSummary(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (!in) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || !j.contains("steps") || !j["steps"].is_array()) return std::nullopt;
  return j;
}

// A finished sequence (fitfeel run's DIR: summary.json over the steps, DIR/<step>/ each step's
// run): every step drawn as that run drew it (its seed, and its seats where the summary says the
// earlier steps left their parts) with its history, the page on the last step.
void ViewFinishedSequence(const ViewArgs& args, const nlohmann::json& summary,
                          const PluginRegistry& registry, LoadOptions load,
                          const view::ServerOptions& options) {
  const fs::path summary_file = fs::path(args.trace) / "summary.json";
  const auto field = [&](const nlohmann::json& j, const char* key) -> const nlohmann::json& {
    if (!j.contains(key)) {
      throw UserError("view: '" + summary_file.string() + "' names no " + key +
                      " for a step or the sequence, so its steps cannot be drawn again");
    }
    return j[key];
  };
  load.writes_outputs = false;
  std::string scenario_file;
  std::vector<std::string> ran, folders;
  std::uint64_t ran_seed = 0;
  std::vector<Eigen::Vector2d> offsets;
  const nlohmann::json& entries = summary["steps"];
  try {
    scenario_file = field(summary, "scenario_file").get<std::string>();
    ran_seed = field(summary, "seed").get<std::uint64_t>();
    for (const nlohmann::json& entry : entries) {
      ran.push_back(field(entry, "step").get<std::string>());
      folders.push_back(field(entry, "folder").get<std::string>());
      const nlohmann::json& um = field(entry, "seated_offset_um");
      offsets.emplace_back(um.at(0).get<double>() * 1e-6, um.at(1).get<double>() * 1e-6);
    }
  } catch (const nlohmann::json::exception& e) {
    throw UserError("view: '" + summary_file.string() + "' is not a sequence's summary (" +
                    e.what() + ")");
  }
  const Sequence sequence = LoadSequence(scenario_file, registry, load);
  std::vector<std::string> now;
  for (const SequenceStep& step : sequence.steps) now.push_back(step.scene.name);
  if (ran != now) {
    throw UserError("view: the steps of '" + summary_file.string() + "' are not those of '" +
                    sequence.file.string() + "': the scenario changed since that run");
  }
  const std::uint64_t seed = args.seed.value_or(ran_seed);
  const std::vector<nlohmann::json> finished(entries.begin(), entries.end());
  std::vector<view::ServedStep> steps(sequence.steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const Scene scene = StepScene(sequence, k, seed, offsets);
    auto model =
        std::make_shared<const view::ViewModel>(scene, scene.run.seed, static_cast<int>(k));
    const plot::RunRecord run = plot::LoadRun(fs::path(args.trace) / folders[k]);
    steps[k].history = HistoryOf(run.trace, *model);
    steps[k].model = std::move(model);
  }
  view::Server server(std::move(steps),
                      view::SequenceMessage(sequence, seed, sequence.steps.size() - 1, finished),
                      options);
  server.Start();
  std::printf(
      "fitfeel view: sequence %s (finished run %s, seed %llu), %zu steps\n  http://%s:%u/\n",
      sequence.name.c_str(), args.trace.c_str(), static_cast<unsigned long long>(seed),
      sequence.steps.size(), args.host.c_str(), server.port());
  std::fflush(stdout);
  Serve(server, args);
}

// With --wait, until a browser has connected.
void WaitForBrowser(const ViewArgs& args, const view::Server& server) {
  if (!args.wait) return;
  std::printf("  waiting for a browser to connect before running\n");
  std::fflush(stdout);
  while (server.clients() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

// What a live view's run takes once the page may start it: waits for a browser where asked, then
// the run's folder, seed and clock, and the interrupt's cooperation (from its first tick on, a
// signal stops the run at a tick boundary and its temporaries are removed).
RunOptions LiveRunOptions(const ViewArgs& args, view::Server& server, std::uint64_t seed,
                          std::optional<InterruptScope>& interrupt) {
  WaitForBrowser(args, server);
  RunOptions run;
  run.out_dir = args.out;
  run.stop = &InterruptFlag();
  run.prepared = [&interrupt](const PreparedScene&) { interrupt->Cooperate(); };
  if (!args.out.empty()) SweepStaleTemporaries(args.out);
  run.seed = seed;
  // A live view is watched at the device's pace unless asked otherwise.
  run.clock = args.virtual_clock ? ClockMode::kVirtual : ClockMode::kRealTime;
  return run;
}

// A sequence run live: its steps in order as `fitfeel run` runs them (RunSequence), each shown
// from when it starts (SequenceView).
void ViewSequence(const ViewArgs& args, const fs::path& file, const PluginRegistry& registry,
                  const LoadOptions& load, const view::ServerOptions& options,
                  std::optional<InterruptScope>& interrupt) {
  const Sequence sequence = LoadSequence(file, registry, load);
  const std::uint64_t seed = args.seed.value_or(sequence.run.seed);
  view::SequenceView viewer(sequence, seed, options);
  view::Server& server = viewer.server();
  server.Start();
  const std::size_t n = sequence.steps.size();
  std::printf("fitfeel view: sequence %s (%s, seed %llu), %zu steps\n  http://%s:%u/\n",
              sequence.name.c_str(), file.string().c_str(), static_cast<unsigned long long>(seed),
              n, args.host.c_str(), server.port());
  std::fflush(stdout);
  const RunOptions run = LiveRunOptions(args, server, seed, interrupt);
  if (!args.out.empty()) {
    for (const SequenceStep& step : sequence.steps) {
      SweepStaleTemporaries(fs::path(args.out) / step.scene.name);
    }
  }
  SequenceWatch watch = viewer.Watch();
  watch.finished = [&, announce = watch.finished](std::size_t k, const RunResult& result,
                                                  const nlohmann::json& entry) {
    announce(k, result, entry);
    const RunStats& s = result.stats;
    std::printf(
        "  step %zu of %zu: %s, %llu ticks, tick compute p50 %.2f us, p99 %.2f us, max "
        "%.2f us; %llu samples dropped\n",
        k + 1, n, sequence.steps[k].scene.name.c_str(), static_cast<unsigned long long>(s.ticks),
        s.compute_us.p50, s.compute_us.p99, s.compute_us.max,
        static_cast<unsigned long long>(viewer.publisher(k).dropped()));
    for (const auto& note : result.notes) std::printf("    %s\n", note.c_str());
    std::fflush(stdout);
  };
  const SequenceResult result = RunSequence(sequence, run, watch);
  if (InterruptSignal() != 0) return;
  interrupt.emplace("fitfeel view",
                    args.out.empty() ? "no outputs written" : "the run's outputs were complete");
  std::printf("  %d viewer client(s)\n", server.clients());
  if (!result.summary.empty()) std::printf("  summary %s\n", result.summary.c_str());
  std::printf("  run finished: the page scrubs each step (Ctrl-C to stop)\n");
  std::fflush(stdout);
  Serve(server, args);
}

// A live view the page changes (--edit) or switches between two scenes (--compare): passes of
// the scene's run in real time until interrupted (or --exit-after seconds after the start).
void ViewLive(const ViewArgs& args, const fs::path& file, const PluginRegistry& registry,
              const LoadOptions& load, const view::ServerOptions& options) {
  if (!args.trace.empty()) throw UserError("view: --edit and --compare run a scene, not --trace");
  if (args.virtual_clock) {
    throw UserError(
        "view: --edit and --compare run the device in real time (a person feels each "
        "change); remove --virtual");
  }
  if (!args.out.empty()) {
    throw UserError(
        "view: --edit and --compare write no outputs (each pass is a new run); "
        "remove --out, and save an edited scene from the page");
  }
  view::LiveSessionOptions live;
  live.server = options;
  live.load = load;
  live.load.writes_outputs = false;
  live.seed = args.seed;
  live.stop = &InterruptFlag();
  live.say = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  const std::optional<fs::path> compare =
      args.compare.empty() ? std::nullopt : std::optional<fs::path>(args.compare);
  view::LiveSession session(file, compare, registry, live);
  session.server().Start();
  std::printf("fitfeel view: %s (%s), %s\n  http://%s:%u/\n", session.rendering().c_str(),
              file.string().c_str(),
              compare ? ("compared with " + compare->string()).c_str() : "edited from the page",
              args.host.c_str(), session.server().port());
  std::fflush(stdout);
  WaitForBrowser(args, session.server());
  std::thread timer;
  std::atomic<bool> done{false};
  if (args.exit_after >= 0.0) {
    timer = std::thread([&] {
      const auto end = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(args.exit_after));
      while (!done.load() && std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      session.Stop();
    });
  }
  session.Run();
  done.store(true);
  if (timer.joinable()) timer.join();
  std::printf("  %llu passes, %llu scenes swapped in, %llu state frames served\n",
              static_cast<unsigned long long>(session.passes()),
              static_cast<unsigned long long>(session.swaps()),
              static_cast<unsigned long long>(session.server().frames_sent()));
  std::fflush(stdout);
}

void View(const ViewArgs& args) {
  std::optional<InterruptScope> interrupt;
  interrupt.emplace("fitfeel view");
  if (!args.trace.empty() && !args.file.empty()) {
    throw UserError("view: give a scenario FILE to run or --trace DIR of a finished run, not both");
  }
  if (args.port > 65535) throw UserError("view: --port must be in 0..65535");
  PluginRegistry registry;
  registry.LoadAll();
  view::ServerOptions options;
  options.host = args.host;
  options.port = static_cast<unsigned short>(args.port);
  options.frame_rate = args.frame_rate;
  options.max_clients = args.max_clients;
  // The run writes its trace and recording only with --out.
  LoadOptions load;
  load.allow_large = args.allow_large;
  load.writes_outputs = !args.out.empty();

  if (!args.trace.empty()) {
    if (const std::optional<nlohmann::json> steps = SequenceSummary(args.trace)) {
      ViewFinishedSequence(args, *steps, registry, load, options);
      return;
    }
    const plot::RunRecord run = plot::LoadRun(args.trace);
    if (!run.summary.scenario_file) {
      throw UserError("view: '" + (fs::path(args.trace) / "summary.json").string() +
                      "' names no scenario_file, so the parts cannot be drawn again");
    }
    if (IsSequenceFile(*run.summary.scenario_file)) {
      throw UserError("view: '" + args.trace + "' is one step of the sequence in '" +
                      *run.summary.scenario_file +
                      "': give --trace the sequence's folder (the one above it) to see every step");
    }
    load.writes_outputs = false;
    const Scene scene = LoadScene(*run.summary.scenario_file, registry, load);
    const std::uint64_t seed = args.seed.value_or(run.summary.seed.value_or(scene.run.seed));
    const view::ViewModel model(scene, seed);
    view::Server server(model, nullptr, HistoryOf(run.trace, model), options);
    server.Start();
    std::printf("fitfeel view: %s (finished run %s, seed %llu)\n  http://%s:%u/\n",
                scene.name.c_str(), args.trace.c_str(), static_cast<unsigned long long>(seed),
                args.host.c_str(), server.port());
    std::fflush(stdout);
    Serve(server, args);
    return;
  }

  const fs::path file = args.file.empty() ? FindDefaultScenario() : fs::path(args.file);
  if (args.edit || !args.compare.empty()) {
    ViewLive(args, file, registry, load, options);
    return;
  }
  if (IsSequenceFile(file)) {
    ViewSequence(args, file, registry, load, options, interrupt);
    return;
  }
  Scene scene = LoadScene(file, registry, load);
  const std::uint64_t seed = args.seed.value_or(scene.run.seed);
  const view::ViewModel model(scene, seed);
  view::TickPublisher publisher(1024, scene.moving);
  view::Server server(model, &publisher, {}, options);
  server.Start();
  std::printf("fitfeel view: %s (%s, seed %llu)\n  http://%s:%u/\n", scene.name.c_str(),
              file.string().c_str(), static_cast<unsigned long long>(seed), args.host.c_str(),
              server.port());
  std::fflush(stdout);
  if (!model.renders_forces()) {
    std::printf("  not running: %s\n", model.status().c_str());
    std::fflush(stdout);
    Serve(server, args);
    return;
  }

  RunOptions run = LiveRunOptions(args, server, seed, interrupt);
  run.observer = &publisher;
  const RunResult result = RunScene(std::move(scene), run);
  // A signal after the last tick: the outputs are complete, main says so.
  if (InterruptSignal() != 0) return;
  // Serving again: a signal ends the process at once.
  interrupt.emplace("fitfeel view",
                    args.out.empty() ? "no outputs written" : "the run's outputs were complete");
  const RunStats& s = result.stats;
  std::printf(
      "  %llu ticks, tick compute p50 %.2f us, p99 %.2f us, max %.2f us; "
      "%d viewer client(s), %llu samples dropped\n",
      static_cast<unsigned long long>(s.ticks), s.compute_us.p50, s.compute_us.p99,
      s.compute_us.max, server.clients(), static_cast<unsigned long long>(publisher.dropped()));
  for (const auto& note : result.notes) std::printf("  %s\n", note.c_str());
  if (!result.paths.trace.empty()) std::printf("  trace   %s\n", result.paths.trace.c_str());
  std::printf("  run finished: the page scrubs it (Ctrl-C to stop)\n");
  std::fflush(stdout);
  Serve(server, args);
}

}  // namespace

void AddViewCommand(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  auto* cmd = app.add_subcommand(
      "view",
      "Serve a live 3D viewer in the browser: runs the scenario (or opens a finished run with "
      "--trace) and shows the parts, contact pressure, resistances, assembly space and force "
      "trace at http://HOST:PORT/");
  cmd->add_option("file", args->file,
                  std::string("scenario file to run, a scene or a sequence of steps (default: ") +
                      kDefaultScenario + ")");
  cmd->add_option("--trace", args->trace,
                  "a finished run's folder (trace.csv, summary.json), or a finished sequence's "
                  "(summary.json over its steps' folders), to scrub instead of running");
  cmd->add_option("--port", args->port, "TCP port (0: any free port; the URL is printed)")
      ->capture_default_str();
  cmd->add_option("--host", args->host,
                  "address to bind (default 127.0.0.1: this machine only; another address "
                  "exposes the viewer to that network)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "seed (overrides run.seed, or the finished run's)");
  cmd->add_option("--out", args->out, "also write the run's outputs to this folder");
  cmd->add_option("--frame-rate", args->frame_rate, "state frames per second, 1..240")
      ->capture_default_str();
  AddIntegerOption(
      cmd, "--max-clients", 1, view::Server::kMaxClientsCap,
      [args](long n) { args->max_clients = static_cast<int>(n); },
      "browser pages served at once (default 64); one more is answered 503");
  cmd->add_option("--exit-after", args->exit_after,
                  "stop serving this many seconds after the run ends (default: serve until "
                  "interrupted)");
  cmd->add_flag("--allow-large", args->allow_large,
                "show a scene whose estimated preparation exceeds 1 GiB or 30 s, or whose --out "
                "files would exceed 4 GiB");
  cmd->add_flag("--wait", args->wait,
                "start the run only once a browser has connected (watch it from the first tick)");
  auto* edit = cmd->add_flag(
      "--edit", args->edit,
      "let the page change the scene while it runs: sizes (ISO 286 classes and fits), form and "
      "texture values, friction, seed; the run goes on in passes, each new scene swapped in "
      "when the part is out of contact");
  cmd->add_option("--compare", args->compare,
                  "a second scenario to compare with FILE: both prepared, the page switches which "
                  "one the device renders (keys A and B) and overlays both traces")
      ->excludes(edit);
  auto* realtime = cmd->add_flag("--realtime", args->realtime,
                                 "real-time clock (the default for view: watch it at 1 kHz)");
  auto* virtual_clock =
      cmd->add_flag("--virtual", args->virtual_clock,
                    "virtual clock: the run finishes at once and the page scrubs it");
  realtime->excludes(virtual_clock);
  cmd->callback([args] { View(*args); });
}

}  // namespace fitfeel::cli
