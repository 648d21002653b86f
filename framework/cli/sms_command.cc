#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace fitfeel::cli {

void AddSmsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("sms", "(being built)");
  cmd->callback([] { throw UnsupportedError("'sms' is not implemented in this build yet"); });
}

}  // namespace fitfeel::cli
