// A scene's part that names a feature of a STEP file (`cad: {file, feature, part, sidecar}`):
// the file read and checked as `fitfeel import` reads it, the feature's keys put in the part.
#include <algorithm>
#include <array>
#include <cmath>
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

using Vec = std::array<double, 3>;

double Dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The part's shape in its mating frame (framework/model/render_mesh.h), the frame the scene's part
// made of feature `index` is drawn in: y along the insertion as `fitfeel import` reads it for a
// pair (the shaft moves towards the hole from the side it lies on), the origin at the shaft's
// leading end or the hole's entrance (a sphere's or seat's centre), x any direction across.
std::shared_ptr<const scenario::CadMesh> MatingFrameMesh(const Import& import, std::size_t index,
                                                         const CadPart& part, bool outer) {
  auto mesh = std::make_shared<scenario::CadMesh>();
  mesh->note = part.mesh_note;
  if (part.mesh.empty()) return mesh;
  const Feature& f = import.features[index];
  Vec y = f.axis;
  for (const Pair& p : import.pairs) {
    if (p.hole != index && p.shaft != index) continue;
    const Feature& hole = import.features[p.hole];
    const Feature& shaft = import.features[p.shaft];
    const auto middle = [&](const Feature& g) {
      return Dot(g.origin, hole.axis) + 0.5 * (g.axial_min + g.axial_max) * Dot(g.axis, hole.axis);
    };
    const double d = middle(shaft) > middle(hole) ? -1.0 : 1.0;
    y = {d * hole.axis[0], d * hole.axis[1], d * hole.axis[2]};
    break;
  }
  Vec o = f.origin;
  if (f.kind != FeatureKind::kSeat && f.kind != FeatureKind::kSphere) {
    const auto end = [&](double t) {
      return Vec{f.origin[0] + t * f.axis[0], f.origin[1] + t * f.axis[1],
                 f.origin[2] + t * f.axis[2]};
    };
    const Vec lo = end(f.axial_min), hi = end(f.axial_max);
    // A shaft leads with its end furthest along the insertion; a hole is entered at its nearest.
    const bool hi_ahead = Dot(hi, y) > Dot(lo, y);
    o = hi_ahead != outer ? hi : lo;
  }
  const Vec any = std::abs(y[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
  const double along = Dot(any, y);
  Vec x = {any[0] - along * y[0], any[1] - along * y[1], any[2] - along * y[2]};
  const double length = std::sqrt(Dot(x, x));
  x = {x[0] / length, x[1] / length, x[2] / length};
  const Vec z = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  mesh->triangles.reserve(part.mesh.size());
  for (std::size_t i = 0; i + 2 < part.mesh.size(); i += 3) {
    const Vec v = {part.mesh[i] - o[0], part.mesh[i + 1] - o[1], part.mesh[i + 2] - o[2]};
    for (const Vec* a : std::array<const Vec*, 3>{&x, &y, &z}) {
      mesh->triangles.push_back(static_cast<float>(Dot(v, *a)));
    }
  }
  return mesh;
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
    scenario::CadPartKeys keys = PartKeys(*import, *index, outer);
    for (const CadPart& p : import->document.parts) {
      if (p.name == part) keys.mesh = MatingFrameMesh(*import, *index, p, outer);
    }
    return keys;
  } catch (const ScenarioError&) {
    throw;
  } catch (const UserError& e) {
    feature_node.Fail("a feature the scene's part can be made of", e.what());
  }
}

}  // namespace

void InstallSceneCadParts() { scenario::SetCadPartResolver(Resolve); }

}  // namespace fitfeel::cad
