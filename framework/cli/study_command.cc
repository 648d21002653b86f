// fitfeel study FILE --pairs N [--seed S] [--threads T] [--out DIR]: a fit study over N part
// pairs (framework/study/README.md).
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
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
};

// Ctrl-C asks the study to stop: the pairs under way finish and the ones done are written.
std::atomic<bool> g_stop{false};
extern "C" void OnInterrupt(int) { g_stop.store(true); }

// Restores the previous SIGINT disposition however the study ends.
class InterruptScope {
 public:
  InterruptScope() {
    g_stop = false;
    struct sigaction action {};
    action.sa_handler = OnInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
  }
  ~InterruptScope() { sigaction(SIGINT, &previous_, nullptr); }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  struct sigaction previous_ {};
};

void Run(const StudyArgs& args) {
  PluginRegistry registry;
  registry.LoadAll();
  study::StudySettings settings;
  settings.pairs = args.pairs;
  settings.seed = args.seed;
  settings.threads =
      args.threads > 0 ? args.threads
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  if (terminal) {
    settings.progress = [](int done, int total) {
      std::fprintf(stderr, "\r  pairs %d / %d", done, total);
      std::fflush(stderr);
    };
  }
  InterruptScope interrupt;
  settings.stop = &g_stop;
  const study::StudyResult result = study::RunStudy(args.file, registry, settings);
  if (terminal) std::fprintf(stderr, "\n");
  const fs::path dir =
      args.out.empty() ? fs::path("out") / (result.scenario + "-study") : fs::path(args.out);
  study::WriteStudy(dir, result);

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
  std::printf("  %zu of %d pairs%s on %d threads in %.2f s (%.1f pairs/s)\n",
              result.pairs.size(), result.requested_pairs,
              result.interrupted ? " (interrupted)" : "", result.threads, result.wall_s,
              result.wall_s > 0 ? n / result.wall_s : 0.0);
  std::printf("  probability of interference %.3f\n", n > 0 ? interfering / n : 0.0);
  std::printf("  axial resistance mean over a pair: p5 %.4g, p25 %.4g, p50 %.4g, p75 %.4g, "
              "p95 %.4g N\n",
              d.p5, d.p25, d.p50, d.p75, d.p95);
  std::printf("  pairs %s\n  study %s\n", (dir / "pairs.csv").c_str(),
              (dir / "study.json").c_str());
}

}  // namespace

void AddStudyCommand(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  auto* cmd = app.add_subcommand(
      "study",
      "A fit study: draw N part pairs from a scenario (pair i seeded from --seed and i), insert "
      "each in virtual time on all cores, write DIR/pairs.csv and DIR/study.json");
  cmd->add_option("file", args->file, "scenario file")->required();
  cmd->add_option("--pairs", args->pairs, "number of part pairs (default 100)")
      ->check(CLI::Range(1, 10'000'000));
  cmd->add_option("--seed", args->seed, "study seed (default 1)");
  cmd->add_option("--threads", args->threads, "worker threads (default: every core)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--out", args->out, "output folder (default: out/<scenario name>-study)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace fitfeel::cli
