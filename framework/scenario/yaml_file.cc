#include "framework/scenario/yaml_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "framework/core/error.h"
#include "framework/core/line_endings.h"

namespace fitfeel::scenario {

ConfigNode LoadYamlFile(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw ScenarioError({name, 0, 0}, "", "a scenario file", "a directory");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw ScenarioError({name, 0, 0}, "", "a readable scenario file",
                        std::string("none that can be opened (") + std::strerror(errno) + ")");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw ScenarioError({name, 0, 0}, "", "a readable scenario file", "a read error");
  }

  ConfigNode root = ConfigNode::Parse(NormalizeLineEndings(text.str()), name);
  if (!root.is_map()) {
    root.Fail("a map of scenario keys (scenario, surface, parts, moving, model, device, run)",
              root.is_null() ? "an empty file" : root.Describe());
  }
  return root;
}

}  // namespace fitfeel::scenario
