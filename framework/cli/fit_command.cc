#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddFitCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("fit", "(being built)");
  cmd->callback([] { throw UnsupportedError("'fit' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
