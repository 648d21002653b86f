#pragma once

#include <filesystem>

#include <CLI/CLI.hpp>

namespace fitfeel::cli {

// Each subcommand lives in its own file and registers itself on the app. A command's callback
// throws fitfeel::UserError for bad input (exit code 2).
void AddRunCommand(CLI::App& app);
void AddValidateCommand(CLI::App& app);
void AddPluginsCommand(CLI::App& app);
void AddFitCommand(CLI::App& app);
void AddSmsCommand(CLI::App& app);
void AddPlotCommand(CLI::App& app);
void AddStabilityCommand(CLI::App& app);
void AddTradeoffCommand(CLI::App& app);
void AddStudyCommand(CLI::App& app);
void AddViewCommand(CLI::App& app);
void AddNewCommand(CLI::App& app);
#ifdef FITFEEL_HAVE_CAD
void AddImportCommand(CLI::App& app);
#endif

// The scenario `run` and `view` take when given none.
inline constexpr const char* kDefaultScenario = "scenarios/paper-case1-h7js6.yaml";
// A file the project ships (a scenario, "scenarios/NAME.yaml"): as given (relative to the current
// folder), then under FITFEEL_SOURCE_DIR, then under ShippedDataDir() (an install's
// share/fitfeel, the build's source tree); empty when it is in none of them.
std::filesystem::path FindShippedFile(const std::filesystem::path& relative);
// FindShippedFile(kDefaultScenario); throws UserError naming the places when it is in none.
std::filesystem::path FindDefaultScenario();

}  // namespace fitfeel::cli
