#pragma once

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

}  // namespace fitfeel::cli
