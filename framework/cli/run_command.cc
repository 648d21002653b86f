#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddRunCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "(being built)");
  cmd->callback([] { throw UnsupportedError("'run' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
