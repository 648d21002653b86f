#include "framework/scenario/yaml_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "framework/core/error.h"
#include "framework/core/line_endings.h"

namespace fitfeel::scenario {
namespace {

SourceLocation At(const std::string& file, const YAML::Mark& mark) {
  if (mark.is_null() || mark.line < 0) return SourceLocation{file, 0, 0};
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

}  // namespace

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

  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(NormalizeLineEndings(text.str()));
  } catch (const YAML::Exception& e) {
    // yaml-cpp's own wording of the syntax error (e.g. "end of map not found") is what was found.
    throw ScenarioError(At(name, e.mark), "", "valid YAML", e.msg);
  }
  if (documents.size() > 1) {
    throw ScenarioError(At(name, documents[1].Mark()), "",
                        "one scene per file (a single YAML document)", "a second document");
  }
  ConfigNode root(documents.empty() ? YAML::Node() : documents.front(), name, "");
  if (!root.is_map()) {
    root.Fail("a map of scenario keys (scenario, surface, parts, moving, model, device, run)",
              documents.empty() ? "an empty file" : root.Describe());
  }
  return root;
}

}  // namespace fitfeel::scenario
