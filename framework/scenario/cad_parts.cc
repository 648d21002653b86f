#include "framework/scenario/cad_parts.h"

#include <map>
#include <mutex>
#include <string>

#include <yaml-cpp/yaml.h>

namespace fitfeel::scenario {

// yaml-cpp's nodes share their data: the handle written to is the scene's own tree.
struct YamlAccess {
  static YAML::Node Node(const ConfigNode& node) { return node.node(); }
};

namespace {

std::mutex resolver_mutex;
std::mutex mesh_mutex;
std::map<std::pair<std::string, std::string>, std::shared_ptr<const CadMesh>>& Meshes() {
  static std::map<std::pair<std::string, std::string>, std::shared_ptr<const CadMesh>> meshes;
  return meshes;
}
std::string MeshKey(const std::filesystem::path& scenario_file) {
  return std::filesystem::absolute(scenario_file).lexically_normal().string();
}
CadPartResolver& Resolver() {
  static CadPartResolver resolver;
  return resolver;
}

// YAML text whose nodes yaml-cpp marks at `at`'s line and column: what the CAD file gives is
// blamed on the part's `cad` map when a surface refuses it.
YAML::Node LoadAt(const SourceLocation& at, const std::string& flow) {
  const int lines = at.line > 0 ? at.line - 1 : 0;
  const int columns = at.column > 0 ? at.column - 1 : 0;
  return YAML::Load(std::string(static_cast<std::size_t>(lines), '\n') +
                    std::string(static_cast<std::size_t>(columns), ' ') + flow);
}

// Sets `keys` into `part`'s map `key`, refusing a key the part gives itself.
void Merge(const ConfigNode& part, const char* key,
           const std::vector<std::pair<std::string, std::string>>& keys, const SourceLocation& at) {
  if (keys.empty()) return;
  YAML::Node target = YamlAccess::Node(part);
  if (std::optional<ConfigNode> own = part.Find(key)) {
    if (!own->is_map()) own->Fail("a map", own->Describe());
    for (const auto& [name, value] : keys) {
      if (own->Has(name)) {
        own->Child(name).Fail("no `" + name + "` beside the part's `cad` (the CAD file gives it)",
                              own->Child(name).Describe());
      }
    }
  } else {
    target[key] = YAML::Node(YAML::NodeType::Map);
  }
  YAML::Node map = target[key];
  for (const auto& [name, value] : keys) map[name] = LoadAt(at, value);
}

void ResolveParts(const ConfigNode& parts, const std::filesystem::path& scenario_file,
                  const std::string& prefix) {
  if (!parts.is_map()) return;
  for (const std::string& name : parts.Keys()) {
    const ConfigNode part = parts.Child(name);
    if (!part.is_map() || !part.Has("cad")) continue;
    const ConfigNode cad = part.Child("cad");
    CadPartResolver resolver;
    {
      const std::lock_guard<std::mutex> lock(resolver_mutex);
      resolver = Resolver();
    }
    if (!resolver) {
      cad.Fail("a part given by its size and geometry: this program reads no CAD files",
               "a `cad` map");
    }
    if (part.Has("size")) {
      part.Child("size").Fail("no `size` beside the part's `cad` (the CAD file gives it)",
                              part.Child("size").Describe());
    }
    const bool outer = part.Child("role").AsOneOf({"inner", "outer"}) == "outer";
    const CadPartKeys keys = resolver(cad, name, outer, scenario_file);
    const SourceLocation at = cad.location();
    YAML::Node target = YamlAccess::Node(part);
    target["size"] = LoadAt(at, keys.size);
    Merge(part, "geometry", keys.geometry, at);
    Merge(part, "form", keys.form, at);
    if (keys.texture && !part.Has("texture")) target["texture"] = LoadAt(at, *keys.texture);
    if (keys.material && !part.Has("material")) target["material"] = LoadAt(at, *keys.material);
    target.remove("cad");
    const std::lock_guard<std::mutex> lock(mesh_mutex);
    Meshes()[{MeshKey(scenario_file), prefix + name}] = keys.mesh;
  }
}

}  // namespace

void SetCadPartResolver(CadPartResolver resolver) {
  const std::lock_guard<std::mutex> lock(resolver_mutex);
  Resolver() = std::move(resolver);
}

std::shared_ptr<const CadMesh> CadMeshOf(const std::filesystem::path& scenario_file,
                                         const std::string& part) {
  const std::lock_guard<std::mutex> lock(mesh_mutex);
  const auto found = Meshes().find({MeshKey(scenario_file), part});
  return found == Meshes().end() ? nullptr : found->second;
}

void ResolveCadParts(const ConfigNode& root, const std::filesystem::path& scenario_file) {
  if (!root.is_map()) return;
  if (std::optional<ConfigNode> parts = root.Find("parts")) ResolveParts(*parts, scenario_file, "");
  if (std::optional<ConfigNode> features = root.Find("features")) {
    if (!features->is_map()) return;
    for (const std::string& name : features->Keys()) {
      const ConfigNode feature = features->Child(name);
      if (!feature.is_map()) continue;
      if (std::optional<ConfigNode> parts = feature.Find("parts")) {
        ResolveParts(*parts, scenario_file, name + "/");
      }
    }
  }
}

}  // namespace fitfeel::scenario
