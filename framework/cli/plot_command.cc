#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"
#include "framework/core/path_check.h"
#include "framework/plot/gnuplot.h"
#include "framework/plot/mapping_chart.h"
#include "framework/plot/pressure_chart.h"
#include "framework/plot/render.h"
#include "framework/plot/run_record.h"
#include "framework/plot/scene_charts.h"
#include "framework/plot/scene_shapes.h"
#include "framework/plot/study_chart.h"
#include "framework/plot/trace_chart.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"
#include "framework/study/study_record.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

// The image path as given: a device or a folder there is refused before anything is drawn.
const std::string& CheckedOutput(const std::string& output) {
  CheckOutputFile("--output", output);
  return output;
}

void PrintWritten(const std::vector<plot::OutputFile>& outputs) {
  for (const auto& output : outputs) std::cout << "wrote " << output.path.string() << "\n";
}

void AddTrace(CLI::App& plot) {
  struct Options {
    std::vector<std::string> dirs;
    std::string output;
    bool log_scale = false;
    bool torque = false;
  };
  auto options = std::make_shared<Options>();
  auto* cmd = plot.add_subcommand(
      "trace", "Axial and radial resistance against insertion depth, one curve per run folder");
  cmd->add_option("DIR", options->dirs, "run folders holding trace.csv and summary.json")
      ->required()
      ->expected(1, -1);
  cmd->add_option("-o,--output", options->output,
                  "image file: .png, .svg, or no extension for both")
      ->required();
  auto* log = cmd->add_flag("--log", options->log_scale,
                            "logarithmic force axes (runs that differ by orders of magnitude)");
  cmd->add_flag("--torque", options->torque,
                "a screw's run (a thread scene): its torque and preload against its turn angle")
      ->excludes(log);
  cmd->callback([options] {
    const auto outputs = plot::ResolveOutputs(CheckedOutput(options->output));
    std::vector<plot::RunRecord> runs;
    for (const auto& dir : options->dirs) runs.push_back(plot::LoadRun(dir));
    plot::Render(options->torque ? plot::MakeTorqueChart(runs)
                                 : plot::MakeTraceChart(runs, options->log_scale),
                 outputs);
    PrintWritten(outputs);
  });
}

void AddMapping(CLI::App& plot) {
  struct Options {
    std::vector<std::string> dirs;
    std::string output;
  };
  auto options = std::make_shared<Options>();
  auto* cmd = plot.add_subcommand(
      "mapping",
      "The safety chain's force mapping (scene force -> device force) and where each run landed");
  cmd->add_option("DIR", options->dirs,
                  "run folders holding summary.json; the first one's mapping is drawn")
      ->required()
      ->expected(1, -1);
  cmd->add_option("-o,--output", options->output,
                  "image file: .png, .svg, or no extension for both")
      ->required();
  cmd->callback([options] {
    const auto outputs = plot::ResolveOutputs(CheckedOutput(options->output));
    const std::vector<fs::path> dirs(options->dirs.begin(), options->dirs.end());
    const plot::MappingChartData data = plot::LoadMappingRuns(dirs);
    for (const std::string& note : data.notes) std::cerr << "fitfeel: note: " << note << "\n";
    plot::RenderMappingChart(data, outputs);
    PrintWritten(outputs);
  });
}

// A run's summary names its scenario file as the run was given it: relative to the folder the run
// started in. Looked up like `fitfeel run`'s default (FindShippedFile): as given, then under
// $FITFEEL_SOURCE_DIR, then among the shipped files.
fs::path FindRunScenario(const std::string& file) {
  const std::string why = WhyNotReadableFile(file);
  if (why.empty()) return file;
  const fs::path found = FindShippedFile(file);
  if (!found.empty() && WhyNotReadableFile(found).empty()) return found;
  throw UserError("the run's scenario file '" + file + "' was not found (" + why +
                  "), nor under FITFEEL_SOURCE_DIR or among the shipped scenarios; give "
                  "--scenario FILE");
}

// Loads the plugins the way `run` and `validate` do, saying which libraries were refused.
std::unique_ptr<PluginRegistry> LoadPlugins() {
  auto registry = std::make_unique<PluginRegistry>();
  registry->LoadAll();
  for (const RefusedLibrary& refused : registry->refused()) {
    std::cerr << "fitfeel: note: plugin library " << refused.library.string()
              << " was not loaded: " << refused.reason << "\n";
  }
  return registry;
}

// The loader's options of a chart: no run output is written; `--allow-large` admits a large
// scene as `run` does.
LoadOptions ChartLoad(bool allow_large) {
  LoadOptions load;
  load.allow_large = allow_large;
  load.writes_outputs = false;
  return load;
}

constexpr const char* kAllowLargeHelp =
    "draw a scene whose estimated preparation exceeds 1 GiB or 30 s";

void AddSms(CLI::App& plot) {
  struct Options {
    std::string scenario;
    std::string part;
    std::optional<std::uint64_t> seed;
    std::string output;
    bool allow_large = false;
  };
  auto options = std::make_shared<Options>();
  auto* cmd = plot.add_subcommand(
      "sms",
      "Unwrapped skin profile variation of each mating surface and the tolerance space at full "
      "insertion");
  cmd->add_option("SCENARIO", options->scenario, "scenario file (YAML)")->required();
  cmd->add_option("--part", options->part, "draw only this part's skin profile");
  AddSeedOption(
      cmd, "--seed", [options](std::uint64_t s) { options->seed = s; },
      "seed of the skin model shapes (default: run.seed; the same range)");
  cmd->add_option("-o,--output", options->output,
                  "image file: .png, .svg, or no extension for both")
      ->required();
  cmd->add_flag("--allow-large", options->allow_large, kAllowLargeHelp);
  cmd->callback([options] {
    const auto outputs = plot::ResolveOutputs(CheckedOutput(options->output));
    const auto registry = LoadPlugins();
    LoadOptions load = ChartLoad(options->allow_large);
    load.allow_non_rendering = true;  // a surface without laws still has skin model shapes
    const plot::SceneShapes shapes =
        plot::GenerateSceneShapes(LoadScene(options->scenario, *registry, load), options->seed);
    const Scene& scene = shapes.scene;
    plot::Render(plot::MakeSceneSmsChart(scene.name, scene.inner, shapes.inner, scene.outer,
                                         shapes.outer, !scene.surface->rotational(), options->part),
                 outputs);
    PrintWritten(outputs);
  });
}

void AddPressure(CLI::App& plot) {
  struct Options {
    std::string dir;
    double depth_mm = 0.0;
    std::string scenario;
    std::string output;
    bool allow_large = false;
  };
  auto options = std::make_shared<Options>();
  auto* cmd = plot.add_subcommand(
      "pressure",
      "Contact pressure map of a run at one insertion depth, with the resultant forces");
  cmd->add_option("DIR", options->dir, "run folder holding trace.csv and summary.json")->required();
  AddQuantityOption(
      cmd, "--depth", Dimension::kDimensionless, -1e4, 1e4,
      [options](double depth) { options->depth_mm = depth; },
      "insertion depth in mm, inside the run's constrained range")
      ->required();
  cmd->add_option("--scenario", options->scenario,
                  "scenario file of the run (default: the one its summary.json names)");
  cmd->add_option("-o,--output", options->output,
                  "image file: .png, .svg, or no extension for both")
      ->required();
  cmd->add_flag("--allow-large", options->allow_large, kAllowLargeHelp);
  cmd->callback([options] {
    const auto outputs = plot::ResolveOutputs(CheckedOutput(options->output));
    const plot::RunRecord run = plot::LoadRun(options->dir);
    plot::RowAtDepth(run.trace, options->depth_mm);  // refuse a depth the run never reached
    std::string file = options->scenario;
    if (file.empty()) {
      if (!run.summary.scenario_file) {
        throw UserError(options->dir +
                        "/summary.json names no scenario file; give --scenario FILE");
      }
      file = *run.summary.scenario_file;
    }
    const auto registry = LoadPlugins();
    Scene scene = LoadScene(FindRunScenario(file), *registry, ChartLoad(options->allow_large));
    if (scene.name != run.summary.scenario) {
      throw UserError("scenario file '" + file + "' holds scenario '" + scene.name +
                      "', but the run in " + options->dir + " was of '" + run.summary.scenario +
                      "'");
    }
    // The run's seed rebuilds the skin model shapes it ran on.
    const plot::SceneShapes shapes = plot::GenerateSceneShapes(std::move(scene), run.summary.seed);
    plot::CheckSameGrids(shapes, run.summary.inner_grid, run.summary.outer_grid);
    const plot::PreparedContact contact = plot::PrepareContact(shapes, run.summary.law);
    const plot::PressureMapData data =
        plot::MakePressureData(run, options->depth_mm, *contact.analyzer, *contact.law,
                               shapes.inner.grid, shapes.scene.moving);
    if (!data.pose_note.empty()) std::cerr << "fitfeel: note: " << data.pose_note << "\n";
    plot::Render(plot::MakePressureChart(data), outputs);
    PrintWritten(outputs);
  });
}

void AddStudy(CLI::App& plot) {
  struct Options {
    std::vector<std::string> dirs;
    std::string reference;
    std::string output;
    bool allow_large = false;
  };
  auto options = std::make_shared<Options>();
  auto* cmd = plot.add_subcommand(
      "study", "Distribution of insertion force over the part pairs of one or more studies");
  cmd->add_option("DIR", options->dirs, "study folders holding pairs.csv and study.json")
      ->required()
      ->expected(1, -1);
  cmd->add_option("--reference", options->reference,
                  "scenario whose mean axial resistance is drawn as a line (e.g. the paper's "
                  "VE1 method, scenarios/paper-case1-ve1.yaml)");
  cmd->add_option("-o,--output", options->output,
                  "image file: .png, .svg, or no extension for both")
      ->required();
  cmd->add_flag("--allow-large", options->allow_large,
                "run a --reference scene whose estimated preparation exceeds 1 GiB or 30 s");
  cmd->callback([options] {
    const auto outputs = plot::ResolveOutputs(options->output);
    std::vector<study::StudyRecord> studies;
    for (const auto& dir : options->dirs) studies.push_back(study::LoadStudy(dir));
    std::optional<plot::ReferenceLine> reference;
    if (!options->reference.empty()) {
      const auto registry = LoadPlugins();
      Scene scene = LoadScene(options->reference, *registry, ChartLoad(options->allow_large));
      const std::string name = scene.name;
      RunOptions run;
      run.clock = ClockMode::kVirtual;
      const RunResult result = RunScene(std::move(scene), run);
      const auto& axial = result.summary.at("axial_resistance_N");
      if (axial.is_null()) {
        throw UserError("--reference " + options->reference +
                        ": the run never reached the "
                        "constrained stage, so it has no axial resistance to draw");
      }
      reference = plot::ReferenceLine{name + " (mean)", axial.at("mean").get<double>()};
    }
    plot::Render(plot::MakeStudyChart(studies, reference), outputs);
    PrintWritten(outputs);
  });
}

}  // namespace

void AddPlotCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("plot", "Draw charts of runs and skin model shapes (gnuplot)");
  cmd->require_subcommand(1);
  AddTrace(*cmd);
  AddSms(*cmd);
  AddPressure(*cmd);
  AddStudy(*cmd);
  AddMapping(*cmd);
}

}  // namespace fitfeel::cli
