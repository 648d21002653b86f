#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddValidateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate", "(being built)");
  cmd->callback([] { throw UnsupportedError("'validate' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
