#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/plot/gnuplot.h"
#include "framework/plot/render.h"
#include "framework/plot/run_record.h"
#include "framework/plot/trace_chart.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

void PrintWritten(const std::vector<plot::OutputFile>& outputs) {
  for (const auto& output : outputs) std::cout << "wrote " << output.path.string() << "\n";
}

void AddTrace(CLI::App& plot) {
  struct Options {
    std::vector<std::string> dirs;
    std::string output;
    bool log_axial = false;
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
  cmd->add_flag("--log", options->log_axial,
                "logarithmic axial-force axis (runs that differ by orders of magnitude)");
  cmd->callback([options] {
    const auto outputs = plot::ResolveOutputs(options->output);
    std::vector<plot::RunRecord> runs;
    for (const auto& dir : options->dirs) runs.push_back(plot::LoadRun(dir));
    plot::Render(plot::MakeTraceChart(runs, options->log_axial), outputs);
    PrintWritten(outputs);
  });
}

void AddSms(CLI::App& plot) {
  auto* cmd = plot.add_subcommand(
      "sms", "Unwrapped skin profile variation of each mating surface and the tolerance space");
  auto scenario = std::make_shared<std::string>();
  cmd->add_option("SCENARIO", *scenario, "scenario file")->required();
  cmd->add_option("--part", "draw only this part");
  cmd->add_option("-o,--output", "image file: .png, .svg, or no extension for both")->required();
  cmd->callback([] {
    throw UnsupportedError(
        "'plot sms' needs scenario loading and skin model shape generation, which this build "
        "does not have yet");
  });
}

void AddPressure(CLI::App& plot) {
  auto* cmd = plot.add_subcommand("pressure", "Contact pressure map of a run at one depth");
  cmd->add_option("DIR", "run folder")->required();
  cmd->add_option("--depth", "insertion depth, mm")->required();
  cmd->add_option("-o,--output", "image file: .png, .svg, or no extension for both")->required();
  cmd->callback([] {
    throw UnsupportedError(
        "'plot pressure' needs scenario loading and the contact analyzer, which this build does "
        "not have yet");
  });
}

}  // namespace

void AddPlotCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("plot", "Draw charts of runs and skin model shapes (gnuplot)");
  cmd->require_subcommand(1);
  AddTrace(*cmd);
  AddSms(*cmd);
  AddPressure(*cmd);
}

}  // namespace fitfeel::cli
