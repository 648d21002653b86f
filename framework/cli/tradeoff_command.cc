// fitfeel tradeoff SCENARIO [-o PREFIX] [--resolutions LIST] [--seeds N] [--duration TIME]
// [--cost p50|p99]:
// speed against accuracy over a ladder of grid resolutions (framework/tradeoff/README.md).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/cli/interrupts.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/path_check.h"
#include "framework/core/quantity.h"
#include "framework/plot/gnuplot.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/stability/stability_map.h"
#include "framework/tradeoff/grid_ladder.h"
#include "framework/tradeoff/tradeoff_chart.h"
#include "framework/tradeoff/tradeoff_study.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

struct TradeoffOptions {
  std::string scenario;
  std::string prefix;
  std::string resolutions;
  int seeds = 10;
  std::string duration;
  std::string cost = "p50";
  bool allow_large = false;
};

bool Contains(const std::vector<Resolution>& ladder, const Resolution& r) {
  for (const Resolution& g : ladder) {
    if (g.rows == r.rows && g.columns == r.columns) return true;
  }
  return false;
}

void Run(const TradeoffOptions& options) {
  // The runs write nothing: until the outputs are written, SIGINT or SIGTERM ends the process at
  // once; then the writes complete.
  InterruptScope interrupt("fitfeel tradeoff");
  // Every input is checked, and gnuplot found, before the first run.
  tradeoff::TradeoffSettings settings;
  settings.seeds = options.seeds;
  settings.allow_large = options.allow_large;
  if (!options.duration.empty()) {
    try {
      settings.duration = ParseQuantity(options.duration, Dimension::kTime);
    } catch (const std::invalid_argument& e) {
      throw UserError("tradeoff: --duration '" + options.duration + "': " + e.what());
    }
    if (!(*settings.duration > 0.0)) throw UserError("tradeoff: --duration must be positive");
  }
  PluginRegistry registry;
  registry.LoadAll();
  const fs::path file = options.scenario;
  // Each run's trace is admitted with the ladder (AdmitLadder), at the study's duration.
  LoadOptions load_options;
  load_options.allow_large = options.allow_large;
  load_options.writes_outputs = false;
  const Scene scene = LoadScene(file, registry, load_options);
  if (options.resolutions.empty()) {
    settings.ladder = tradeoff::DefaultLadder();
    // The scene's own grid and the surface type's automatic one join the ladder (auto is
    // reported once if it resolves to a ladder grid).
    if (!scene.model.resolution.is_auto() && !Contains(settings.ladder, scene.model.resolution)) {
      settings.ladder.push_back(scene.model.resolution);
    }
    settings.ladder.push_back(Resolution{});
    // Grids of the default ladder the scene cannot take, or would not prepare within the
    // large-scene thresholds, are left out (said); a grid the user names is refused instead.
    std::vector<std::string> left_out;
    settings.ladder =
        tradeoff::AdmittedGrids(scene, settings.ladder, options.allow_large, &left_out);
    for (const std::string& grid : left_out) {
      std::cerr << "tradeoff: note: the default ladder leaves out " << grid << "\n";
    }
  } else {
    settings.ladder = tradeoff::ParseLadder(options.resolutions);
  }
  tradeoff::AdmitLadder(scene, settings);  // before gnuplot is looked for or anything runs
  const fs::path prefix =
      options.prefix.empty() ? fs::path(scene.name + "-tradeoff") : fs::path(options.prefix);
  if (prefix.filename().empty()) throw UserError("tradeoff: -o needs a file name prefix");
  const fs::path folder = prefix.parent_path().empty() ? fs::path(".") : prefix.parent_path();
  if (const std::string why = WhyNotFolder(folder); !why.empty()) {
    throw UserError("tradeoff: output folder '" + folder.string() + "' " + why);
  }
  plot::Gnuplot::Find();  // UnsupportedError now rather than after the runs
  const fs::path csv = prefix.string() + ".csv";
  CheckOutputFile("-o", prefix);
  for (const char* extension : {".csv", ".png", ".svg"}) {
    CheckOutputFile("-o", prefix.string() + extension);
  }
  const std::vector<plot::OutputFile> images = {
      {prefix.string() + ".png", plot::ImageFormat::kPng},
      {prefix.string() + ".svg", plot::ImageFormat::kSvg}};

  settings.progress = [](const std::string& line) { std::cerr << "tradeoff: " << line << "\n"; };
  const auto load = [&] { return LoadScene(file, registry, load_options); };
  const std::vector<tradeoff::GridRow> rows = tradeoff::RunTradeoff(load, settings);

  const double duration = settings.duration ? *settings.duration : scene.run.duration;
  char title[512];
  std::snprintf(title, sizeof title,
                "%s: accuracy against cost, %d seeds per grid from seed %llu, %g s each",
                scene.name.c_str(), settings.seeds, static_cast<unsigned long long>(scene.run.seed),
                duration);
  interrupt.Cooperate();
  SweepStaleTemporaries(folder);
  tradeoff::RenderTradeoffChart(
      rows, title, options.cost == "p99" ? tradeoff::TickCost::kP99 : tradeoff::TickCost::kP50,
      images);
  WriteFileAtomically(csv, tradeoff::TradeoffCsv(rows));

  std::printf(
      "%s: %d seeds per grid (different grids draw different shapes from one seed, so "
      "grids are compared over seeds)\n",
      scene.name.c_str(), settings.seeds);
  std::printf("%-22s %9s %9s %9s %9s %10s %8s %9s %9s %9s %8s\n", "grid", "cells", "prep_s",
              "p50_us", "p99_us", "mean_N", "sd_N", "bias_N", "rms_N", "max_N", "noise_N");
  for (const tradeoff::GridRow& r : rows) {
    std::printf("%-22s %9ld %9.3g %9.3g %9.3g %10.4g %8.3g %9.3g %9.3g %9.3g %8.3g%s\n",
                r.label.c_str(), r.inner_cells, r.prepare_seconds, r.tick_p50_us, r.tick_p99_us,
                r.mean_axial_N, r.sd_axial_N, r.bias_N, r.rms_error_N, r.max_error_N, r.noise_rms_N,
                r.reference ? "  reference" : "");
  }
  std::cout << "wrote " << csv.string() << ", " << images[0].path.string() << ", "
            << images[1].path.string() << "\n";
}

}  // namespace

void AddTradeoffCommand(CLI::App& app) {
  auto options = std::make_shared<TradeoffOptions>();
  auto* cmd = app.add_subcommand(
      "tradeoff",
      "Speed against accuracy: run the scene (virtual clock) at a ladder of grid resolutions, "
      "each with several seeds, and chart the error of the seed-averaged trace against the "
      "finest grid over the prepare time and over the tick compute time (median or 99th "
      "percentile, --cost). Several seeds because a different grid "
      "draws a different skin model shape "
      "from the same seed: one seed per grid would mix discretisation error with sampling "
      "variation. Writes PREFIX.csv, PREFIX.png and PREFIX.svg");
  cmd->add_option("scenario", options->scenario, "Scenario file")->required();
  cmd->add_option("-o,--output", options->prefix,
                  "Output prefix (default: <scenario name>-tradeoff in the current folder)");
  cmd->add_option("--resolutions", options->resolutions,
                  "Grids ROWSxCOLUMNS per part, comma-separated, 'auto' for the surface type's "
                  "(default: 8x36,10x72,20x90,20x180,40x180,40x360,80x720,160x1440, the "
                  "scene's grid and auto); the finest is the reference");
  AddIntegerOption(
      cmd, "--seeds", 1, 1000, [options](long n) { options->seeds = static_cast<int>(n); },
      "Runs per grid, seeds run.seed, run.seed+1, ... (default 10)");
  cmd->add_option("--duration", options->duration,
                  "Run duration, overrides run.duration (e.g. '2 s')");
  cmd->add_option("--cost", options->cost,
                  "Tick time on the chart's x axis: p50 (default) or p99. A table-driven law's "
                  "median tick barely depends on the grid; its p99 does")
      ->check(CLI::IsMember({"p50", "p99"}));
  cmd->add_flag("--allow-large", options->allow_large,
                "run grids whose estimated preparation exceeds 1 GiB or 30 s, traces over 4 GiB, "
                "or a ladder whose traces held for the comparison exceed 1 GiB");
  cmd->callback([options] { Run(*options); });
}

}  // namespace fitfeel::cli
