#pragma once

// From what the STEP reader gave (cad_document.h) to a scene: the checks of every PMI value, the
// sidecar's tolerances beside them, the mating features of each part and the pairs they form,
// and the scenario text. No Open CASCADE here: the reader's output is plain data.

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "framework/cad/cad_document.h"
#include "framework/scenario/cad_parts.h"

namespace fitfeel::cad {

// A revolved feature is concave (a hole, a taper hole, a spherical seat: the material outside
// the surface) or convex (a cylinder, a cone, a sphere); a plane is neither.
enum class FeatureKind { kHole, kShaft, kTaperHole, kCone, kSeat, kSphere, kPlane };

// Faces of one part that make one feature: a hole split into two half-cylinders is one hole.
struct Feature {
  std::string part;
  std::string name;  // "hole-1", "cylinder-2", "cone-1", "seat-1": by kind, size, position
  FeatureKind kind = FeatureKind::kPlane;
  std::vector<int> faces;
  std::array<double, 3> origin{};       // on the axis; a sphere's centre; on a plane
  std::array<double, 3> axis{0, 0, 1};  // unit; a plane's normal
  double ref_radius = 0.0;              // at `origin`, m
  double slope = 0.0;                   // the radius' change along `axis` (a cone's tan, signed)
  // The nominal size: a cylinder's or sphere's diameter, a cone's at its small end (the
  // conical surface's reference plane), m.
  double diameter = 0.0;
  double large_diameter = 0.0;  // a cone's at its large end
  double axial_min = 0.0;       // extent along `axis` from `origin`
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

// A concave feature of one part and the convex one of another that it mates with: coaxial
// cylinders, coaxial cones of one taper, or concentric spheres, of one nominal size.
struct Pair {
  std::size_t hole = 0;  // index in Import::features
  std::size_t shaft = 0;
};

// What the sidecar gives a feature besides its tolerances.
struct FeatureSettings {
  std::optional<double> outer_diameter;  // of the ring round a hole in a part with no outside
  std::optional<double> position;        // ISO 1101 position zone's diameter (several features)
};

struct Import {
  CadDocument document;
  std::vector<Feature> features;
  std::map<std::size_t, FeatureTolerances> tolerances;  // by feature index
  std::vector<Pair> pairs;
  std::map<std::size_t, FeatureSettings> settings;  // by feature index, from the sidecar
  std::vector<std::string> ignored;                 // PMI read and not used, said in the listing
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

// The scenario (YAML text): with `pair` (0-based) that pair's; without, the only pair's, or all
// pairs as a several-feature scene when they join the same two parts along parallel axes with a
// surface that slides along them (docs/assemblies.md). Throws UserError when there is no pair,
// when several pairs form no such joint (naming `--pair`), or a part lacks what the scene needs.
std::string ScenarioText(const Import& import, const std::string& name,
                         const std::string& source_file,
                         std::optional<std::size_t> pair = std::nullopt);

// What a part of a scene takes from `feature` (an index in import.features) with the role
// `outer`: its size, the geometry of the surface the feature's kind asks for, its form, and the
// sidecar's chamfer, texture and material. Throws UserError as ScenarioText does.
scenario::CadPartKeys PartKeys(const Import& import, std::size_t feature, bool outer);

// Lets every scene this process loads name CAD features in its parts (framework/scenario/
// cad_parts.h): each file read once, through ReadStep, with the import's checks.
void InstallSceneCadParts();

}  // namespace fitfeel::cad
