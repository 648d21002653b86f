// A scene's part that names a feature of a STEP file (`cad: {file, feature, part, sidecar}`):
// the file read and checked as `fitfeel import` reads it, the feature's keys put in the part.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "framework/cad/import.h"
#include "framework/cad/isolated_read.h"
#include "framework/core/config_node.h"
#include "framework/core/error.h"

namespace fitfeel::cad {
namespace {

namespace fs = std::filesystem;

// A path the scene gives, from the scene's folder when relative; refused where it is written
// when no such file exists.
fs::path ExistingFile(const ConfigNode& node, const fs::path& scenario_file, const char* what) {
  fs::path path = node.AsString();
  if (path.is_relative()) path = scenario_file.parent_path() / path;
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    node.Fail(std::string(what) + " (a path from the scenario's folder)",
              "'" + node.AsString() + "', which is no file");
  }
  return path;
}

// Each STEP file and sidecar read once a process: a scene names a file for each of its parts.
std::shared_ptr<const Import> ImportOf(const ConfigNode& file_node, const fs::path& file,
                                       const std::optional<fs::path>& sidecar) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, std::string>, std::shared_ptr<const Import>> cache;
  const std::pair<std::string, std::string> key{fs::absolute(file).string(),
                                                sidecar ? fs::absolute(*sidecar).string() : ""};
  const std::lock_guard<std::mutex> lock(mutex);
  const auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  std::shared_ptr<const Import> import;
  try {
    import = std::make_shared<const Import>(BuildImport(ReadStep(file), sidecar));
  } catch (const ScenarioError&) {
    throw;  // the sidecar's, at its own line
  } catch (const UserError& e) {
    file_node.Fail("a STEP file the import reads", e.what());
  }
  cache.emplace(key, import);
  return import;
}

scenario::CadPartKeys Resolve(const ConfigNode& cad, const std::string& part_name, bool outer,
                              const fs::path& scenario_file) {
  if (!cad.is_map()) cad.Fail("a map {file, feature} (and part, sidecar)", cad.Describe());
  cad.ExpectOnlyKeys({"file", "feature", "part", "sidecar"});
  const ConfigNode file_node = cad.Child("file");
  const fs::path file = ExistingFile(file_node, scenario_file, "a STEP file");
  std::optional<fs::path> sidecar;
  if (std::optional<ConfigNode> node = cad.Find("sidecar")) {
    sidecar = ExistingFile(*node, scenario_file, "a sidecar file");
  }
  const std::shared_ptr<const Import> import = ImportOf(file_node, file, sidecar);
  const std::optional<ConfigNode> part_node = cad.Find("part");
  const std::string part = part_node ? part_node->AsString() : part_name;
  bool known = false;
  std::string parts;
  for (const CadPart& p : import->document.parts) {
    known = known || p.name == part;
    parts += (parts.empty() ? "" : ", ") + p.name;
  }
  if (!known) {
    (part_node ? *part_node : cad)
        .Fail("a part of " + file_node.AsString() + " (" + parts + ")" +
                  (part_node ? "" : ", as the scene's part is named, or `part`"),
              "'" + part + "'");
  }
  const ConfigNode feature_node = cad.Child("feature");
  const std::string feature = feature_node.AsString();
  std::optional<std::size_t> index;
  std::string names;
  for (std::size_t i = 0; i < import->features.size(); ++i) {
    const Feature& f = import->features[i];
    if (f.part != part) continue;
    names += (names.empty() ? "" : ", ") + f.name;
    const bool by_face =
        feature.size() > 1 && feature[0] == '#' &&
        std::find(f.faces.begin(), f.faces.end(), std::atoi(feature.c_str() + 1)) != f.faces.end();
    if (f.name == feature || by_face) index = i;
  }
  if (!index) feature_node.Fail("a feature of " + part + " (" + names + ")", "'" + feature + "'");
  const Feature& f = import->features[*index];
  const bool concave = f.kind == FeatureKind::kHole || f.kind == FeatureKind::kTaperHole ||
                       f.kind == FeatureKind::kSeat;
  if (f.kind != FeatureKind::kPlane && concave != outer) {
    feature_node.Fail(
        std::string(outer ? "a hole, taper hole or seat" : "a cylinder, cone or sphere") +
            " for a part with role " + (outer ? "outer" : "inner"),
        "'" + feature + "'");
  }
  try {
    return PartKeys(*import, *index, outer);
  } catch (const ScenarioError&) {
    throw;
  } catch (const UserError& e) {
    feature_node.Fail("a feature the scene's part can be made of", e.what());
  }
}

}  // namespace

void InstallSceneCadParts() { scenario::SetCadPartResolver(Resolve); }

}  // namespace fitfeel::cad
