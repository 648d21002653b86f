#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "framework/cli/command_line_errors.h"
#include "framework/cli/commands.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#ifdef FITFEEL_HAVE_CAD
#include "framework/cad/import.h"
#endif

namespace {

// A message as printed: control characters a file or argument brought in (a form feed in a key,
// an escape sequence in a name) shown as \xHH, since they would break the line or act on the
// terminal; a message of several lines (a plugin search, a quoted block of YAML) with its later
// lines indented when `indent`, so that every line a user reads starts with "fitfeel...",
// "usage:" or spaces.
std::string Printable(const std::string& message, bool indent) {
  std::string out;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += indent ? "\n  " : "\n";
    } else if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '\n')) out.pop_back();
  return out;
}

// "fitfeel run: interrupted by SIGINT after ...": the command's own name opens the line, as its
// summary does. Exit code 128 + signal.
int ReportInterrupt(const CLI::App& app, const std::string& what) {
  int signal = fitfeel::InterruptSignal();
  if (signal == 0) signal = SIGINT;  // a stop flag set without a signal: reported as Ctrl-C
  std::cerr << fitfeel::cli::CommandPath(fitfeel::cli::GivenCommand(app)) << ": interrupted by "
            << fitfeel::SignalName(signal) << " " << what << "\n";
  return fitfeel::InterruptExitCode(signal);
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
  fitfeel::cli::AddNewCommand(app);
#ifdef FITFEEL_HAVE_CAD
  fitfeel::cli::AddImportCommand(app);
  // Scenes this command loads may name CAD features in their parts (docs/cad-import.md).
  fitfeel::cad::InstallSceneCadParts();
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    // Every refusal of CLI11's, whatever its kind, in the project's words with the usage line.
    std::cerr << Printable(fitfeel::cli::DescribeParseError(e, app), false) << "\n";
    return 2;
  } catch (const fitfeel::cli::OptionError& e) {
    std::cerr << Printable(fitfeel::cli::DescribeOptionError(e.what(), app), false) << "\n";
    return 2;
  } catch (const fitfeel::Interrupted& e) {
    return ReportInterrupt(app, e.what());
  } catch (const fitfeel::UserError& e) {
    std::cerr << "fitfeel: error: " << Printable(e.what(), true) << "\n";
    return 2;
  } catch (const std::exception& e) {
    // A failure after an interrupt is the interrupt's doing (a helper process killed by the same
    // Ctrl-C, a write cut short): reported as the interrupt, with what failed.
    if (fitfeel::InterruptSignal() != 0) {
      return ReportInterrupt(app, std::string("(") + e.what() + ")");
    }
    std::cerr << "fitfeel: internal error: " << Printable(e.what(), true) << "\n";
    return 1;
  }
  // A signal that arrived once the outputs were being put in place: they are complete.
  if (fitfeel::InterruptSignal() != 0) {
    return ReportInterrupt(app, "once its work was complete; its outputs were kept");
  }
  return 0;
}
