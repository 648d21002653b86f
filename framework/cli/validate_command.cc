#include <iostream>
#include <memory>
#include <string>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/scenario/scene_summary.h"
#include "framework/scenario/sequence.h"

namespace fitfeel::cli {

// `fitfeel validate FILE`: loads the plugins and the scene exactly as `run` would, prints what
// the scene holds and "valid". It writes no file; a bad scene throws ScenarioError (exit code 2).
void AddValidateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "validate", "Check a scenario file (units, ranges, plugins) without running it");
  auto file = std::make_shared<std::string>();
  cmd->add_option("file", *file, "Scenario file (YAML)")->required();
  auto allow_large = std::make_shared<bool>(false);
  cmd->add_flag("--allow-large", *allow_large,
                "accept a scene whose estimated preparation exceeds 1 GiB or 30 s, or whose "
                "trace and recording would exceed 4 GiB, as run does");
  cmd->callback([file, allow_large] {
    PluginRegistry registry;
    registry.LoadAll();
    for (const RefusedLibrary& refused : registry.refused()) {
      std::cerr << "fitfeel: note: plugin library " << refused.library.string()
                << " was not loaded: " << refused.reason << "\n";
    }
    LoadOptions options;
    options.allow_large = *allow_large;
    if (IsSequenceFile(*file)) {
      std::cout << DescribeSequence(LoadSequence(*file, registry, options)) << "valid\n";
      return;
    }
    const Scene scene = LoadScene(*file, registry, options);
    std::cout << DescribeScene(scene) << "valid\n";
  });
}

}  // namespace fitfeel::cli
