#pragma once

// From what the STEP reader gave (cad_document.h) to a scene: the checks of every PMI value, the
// sidecar's tolerances beside them, the mating features of each part and the pairs they form,
// and the scenario text. No Open CASCADE here: the reader's output is plain data.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "framework/cad/cad_document.h"

namespace fitfeel::cad {

enum class FeatureKind { kHole, kShaft, kPlane, kCone, kSphere };

// Faces of one part that make one feature: a hole split into two half-cylinders is one hole.
struct Feature {
  std::string part;
  std::string name;  // "hole-1", "cylinder-2", "plane-1": by kind, then size, then position
  FeatureKind kind = FeatureKind::kPlane;
  std::vector<int> faces;
  std::array<double, 3> origin{};
  std::array<double, 3> axis{0, 0, 1};
  double diameter = 0.0;  // geometric, m (holes and cylinders; spheres)
  double axial_min = 0.0;
  double axial_max = 0.0;
};

struct Size {
  double nominal = 0.0;
  double lower = 0.0;
  double upper = 0.0;
  std::string iso_class;  // empty for explicit deviations
  std::string source;     // "STEP #192", "sidecar"
};

struct FeatureTolerances {
  std::optional<Size> size;
  std::map<std::string, std::pair<double, std::string>> form;  // "roundness" -> (value, source)
};

struct Pair {
  std::size_t hole = 0;  // index in Import::features
  std::size_t shaft = 0;
};

struct Import {
  CadDocument document;
  std::vector<Feature> features;
  std::map<std::size_t, FeatureTolerances> tolerances;  // by feature index
  std::vector<Pair> pairs;
  std::vector<std::string> ignored;  // PMI read and not used, said in the listing
  // What the sidecar adds that CAD does not carry, as YAML flow text: per part "chamfer",
  // "texture", "material"; and the scenario's own sections.
  std::map<std::string, std::map<std::string, std::string>> part_extras;
  std::vector<std::pair<std::string, std::string>> scenario_sections;  // key, YAML block text
};

// Features, checked PMI, the sidecar's values (a file, or none) and the pairs. Throws UserError
// naming the STEP entity (and the sidecar's line) for every refusal.
Import BuildImport(CadDocument document, const std::optional<std::filesystem::path>& sidecar);

// The listing `fitfeel import` prints: parts, features, tolerances and their sources, pairs.
std::string DescribeImport(const Import& import);

// The scenario (YAML text) of the first pair: the cylindrical surface, the hole's part outer.
// Throws UserError when there is no pair or a part lacks what the scene needs.
std::string ScenarioText(const Import& import, const std::string& name,
                         const std::string& source_file);

}  // namespace fitfeel::cad
