#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddStabilityCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("stability", "(being built)");
  cmd->callback([] { throw UnsupportedError("'stability' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
