#pragma once

#include <filesystem>

#include "framework/core/config_node.h"
#include "framework/core/export.h"

namespace fitfeel::scenario {

// Reads one scenario file into its root node. A file that cannot be read, is not valid YAML
// (reported at the parser's line:column) or holds more than one document throws ScenarioError.
FITFEEL_API ConfigNode LoadYamlFile(const std::filesystem::path& file);

}  // namespace fitfeel::scenario
