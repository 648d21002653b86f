#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddPluginsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("plugins", "(being built)");
  cmd->callback([] { throw UnsupportedError("'plugins' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
