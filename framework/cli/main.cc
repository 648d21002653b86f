#include <cstdio>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "framework/cli/commands.h"
#include "framework/core/error.h"

int main(int argc, char** argv) {
  CLI::App app{
      "fitfeel: feel a fit. Renders the resistance of assembling two machined parts, computed "
      "from their ISO GPS tolerances, at 1 kHz on a haptic device."};
  app.require_subcommand(1);
  app.set_version_flag("--version", FITFEEL_VERSION);
  fitfeel::cli::AddRunCommand(app);
  fitfeel::cli::AddValidateCommand(app);
  fitfeel::cli::AddPluginsCommand(app);
  fitfeel::cli::AddFitCommand(app);
  fitfeel::cli::AddSmsCommand(app);
  fitfeel::cli::AddPlotCommand(app);
  fitfeel::cli::AddStabilityCommand(app);
  fitfeel::cli::AddTradeoffCommand(app);
  fitfeel::cli::AddStudyCommand(app);
  fitfeel::cli::AddViewCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const fitfeel::UserError& e) {
    std::cerr << "fitfeel: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "fitfeel: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
