// fitfeel study FILE --pairs N [--seed S] [--threads T] [--out DIR]: a fit study over N part
// pairs (framework/study/README.md).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "framework/cli/commands.h"
#include "framework/cli/interrupts.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/plot/study_chart.h"
#include "framework/plugin/registry.h"
#include "framework/study/study.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

struct StudyArgs {
  std::string file;
  int pairs = 100;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: every core
  std::string out;
  bool allow_large = false;
};

void Run(const StudyArgs& args) {
  InterruptScope interrupt("fitfeel study");
  const fs::path dir = args.out.empty()
                           ? fs::path("out") / (fs::path(args.file).stem().string() + "-study")
                           : fs::path(args.out);
  CheckOutputFolder("--out", dir);
  PluginRegistry registry;
  registry.LoadAll();
  study::StudySettings settings;
  settings.pairs = args.pairs;
  settings.seed = args.seed;
  settings.allow_large = args.allow_large;
  settings.threads = args.threads > 0
                         ? args.threads
                         : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  if (terminal) {
    settings.progress = [](int done, int total) {
      std::fprintf(stderr, "\r  pairs %d / %d", done, total);
      std::fflush(stderr);
    };
  }
  SweepStaleTemporaries(dir);
  // SIGINT or SIGTERM stops the study: no new pair starts, the pairs under way finish, and the
  // pairs done so far are written, complete and valid, marked "interrupted" in study.json.
  interrupt.Cooperate();
  settings.stop = &InterruptFlag();
  const study::StudyResult result = study::RunStudy(args.file, registry, settings);
  if (terminal) std::fprintf(stderr, "\n");
  if (result.pairs.empty() && result.interrupted) {
    throw Interrupted("before any pair was done; no outputs written");
  }
  study::WriteStudy(dir, result);
  // The chart from the files just written (what `fitfeel plot study DIR` draws): a failure to
  // draw leaves the two data files, complete.
  plot::WriteStudyChart(dir);

  std::vector<double> mean;
  int interfering = 0;
  for (const auto& p : result.pairs) {
    mean.push_back(p.axial_mean_N);
    if (p.interfering) ++interfering;
  }
  const study::Distribution d = study::Describe(mean);
  const double n = static_cast<double>(result.pairs.size());
  std::printf("fitfeel study: %s (%s), seed %llu\n", result.scenario.c_str(),
              result.scenario_file.c_str(), static_cast<unsigned long long>(result.seed));
  std::printf("  %zu of %d pairs%s on %d threads in %.2f s (%.1f pairs/s)\n", result.pairs.size(),
              result.requested_pairs, result.interrupted ? " (interrupted)" : "", result.threads,
              result.wall_s, result.wall_s > 0 ? n / result.wall_s : 0.0);
  std::printf("  probability of interference %.3f\n", n > 0 ? interfering / n : 0.0);
  std::printf(
      "  axial resistance mean over a pair: p5 %.4g, p25 %.4g, p50 %.4g, p75 %.4g, "
      "p95 %.4g N\n",
      d.p5, d.p25, d.p50, d.p75, d.p95);
  std::printf("  pairs %s\n  study %s\n  chart %s\n", (dir / "pairs.csv").c_str(),
              (dir / "study.json").c_str(), (dir / "study.png").c_str());
  if (result.interrupted) {
    std::fflush(stdout);
    throw Interrupted("after " + std::to_string(result.pairs.size()) + " of " +
                      std::to_string(result.requested_pairs) + " pairs; the pairs done were " +
                      "written to '" + dir.string() + "' (study.json: \"interrupted\": true)");
  }
}

}  // namespace

void AddStudyCommand(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  auto* cmd = app.add_subcommand(
      "study",
      "A fit study: draw N part pairs from a scenario (pair i seeded from --seed and i), insert "
      "each in virtual time on all cores, write DIR/pairs.csv, DIR/study.json and DIR/study.png");
  cmd->add_option("file", args->file, "scenario file")->required();
  AddIntegerOption(
      cmd, "--pairs", 1, 10'000'000, [args](long n) { args->pairs = static_cast<int>(n); },
      "number of part pairs (default 100)");
  AddSeedOption(
      cmd, "--seed", [args](std::uint64_t s) { args->seed = s; },
      "study seed (default 1; the range of run.seed)");
  AddIntegerOption(
      cmd, "--threads", 1, 1024, [args](long t) { args->threads = static_cast<int>(t); },
      "worker threads (default: every core)");
  cmd->add_flag("--allow-large", args->allow_large,
                "run a scene whose estimated preparation exceeds 1 GiB or 30 s");
  cmd->add_option("--out", args->out,
                  "output folder (default: out/<scenario file name without .yaml>-study)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace fitfeel::cli
