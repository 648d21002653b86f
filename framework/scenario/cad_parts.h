#pragma once

// A part of a scene may name a feature of a CAD file instead of its size and geometry:
//
//   parts:
//     shaft: {role: inner, cad: {file: parts.step, feature: cylinder-1}, material: ...}
//
// The framework does not read CAD files (Open CASCADE stays in framework/cad/): a host that has
// the CAD import installs a resolver, and the loader puts what it gives in place of `cad` before
// the part is parsed. Without one, a `cad` map is refused where it stands.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/config_node.h"
#include "framework/core/export.h"

namespace fitfeel::scenario {

// A CAD part's own shape, for a viewer to draw in place of the part's primitive surface: 9 numbers
// a triangle (its corners' x y z, m) in the part's mating frame (framework/model/render_mesh.h),
// or no triangles and `note` saying why.
struct CadMesh {
  std::vector<float> triangles;
  std::string note;
};

// What a CAD feature gives a part's map, as YAML flow text per key.
struct CadPartKeys {
  std::string size;
  std::vector<std::pair<std::string, std::string>> geometry;
  std::vector<std::pair<std::string, std::string>> form;
  std::optional<std::string> texture;   // the CAD file's sidecar's, if it gives one
  std::optional<std::string> material;  // likewise
  std::shared_ptr<const CadMesh> mesh;  // null: the resolver gives no shape
};

// `cad`: the part's `cad` map (its checks fail at its own keys); `part`: the part's name in the
// scene; `outer`: its role; `scenario_file`: where relative file names start.
using CadPartResolver =
    std::function<CadPartKeys(const ConfigNode& cad, const std::string& part, bool outer,
                              const std::filesystem::path& scenario_file)>;

// Installs (or, with an empty function, removes) the resolver every later scene load uses.
FITFEEL_API void SetCadPartResolver(CadPartResolver resolver);

// The shape the resolver gave the part `part` of the scene loaded from `scenario_file` (the
// scene's parts; a feature's part as "feature/part"), kept beside the scene so that the parts'
// specs stay as plugins know them; null for a part given by its size and geometry.
FITFEEL_API std::shared_ptr<const CadMesh> CadMeshOf(const std::filesystem::path& scenario_file,
                                                     const std::string& part);

// Replaces every part's `cad` map under `root` (its `parts`, and each feature's) by the keys the
// resolver gives: `size`, `geometry` and `form` merged with what the part gives itself (a key
// given by both is refused), `texture` and `material` where the part gives none.
void ResolveCadParts(const ConfigNode& root, const std::filesystem::path& scenario_file);

}  // namespace fitfeel::scenario
