#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddPlotCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("plot", "(being built)");
  cmd->callback([] { throw UnsupportedError("'plot' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
