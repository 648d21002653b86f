#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "framework/cli/command_line_errors.h"
#include "framework/cli/commands.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"

namespace {

// A message of several lines (a plugin search, a quoted block of YAML) with its later lines
// indented: every line a user reads starts with "fitfeel...", "usage:" or spaces.
std::string Indented(const std::string& message) {
  std::string out;
  for (const char c : message) {
    out += c;
    if (c == '\n') out += "  ";
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '\n')) out.pop_back();
  return out;
}

}  // namespace

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
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    // Every refusal of CLI11's, whatever its kind, in the project's words with the usage line.
    std::cerr << fitfeel::cli::DescribeParseError(e, app) << "\n";
    return 2;
  } catch (const fitfeel::cli::OptionError& e) {
    std::cerr << fitfeel::cli::DescribeOptionError(e.what(), app) << "\n";
    return 2;
  } catch (const fitfeel::UserError& e) {
    std::cerr << "fitfeel: error: " << Indented(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "fitfeel: internal error: " << Indented(e.what()) << "\n";
    return 1;
  }
  return 0;
}
