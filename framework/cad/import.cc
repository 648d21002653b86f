#include "framework/cad/import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "framework/core/config_node.h"
#include "framework/core/error.h"
#include "framework/iso286/iso286.h"

namespace fitfeel::cad {
namespace {

using Vec = std::array<double, 3>;

// Geometry the writer and reader round to about 1e-7 of the reader's millimetres.
constexpr double kLinearTolerance = 1e-7;  // m
constexpr double kAngularTolerance = 1e-9;

double Dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec Sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// Distance of `p` from the line through `origin` along the unit `axis`.
double FromAxis(const Vec& p, const Vec& origin, const Vec& axis) {
  const Vec d = Sub(p, origin);
  const double along = Dot(d, axis);
  return std::sqrt(std::max(0.0, Dot(d, d) - along * along));
}

bool SameLine(const Vec& o1, const Vec& a1, const Vec& o2, const Vec& a2) {
  return std::abs(std::abs(Dot(a1, a2)) - 1.0) < kAngularTolerance &&
         FromAxis(o2, o1, a1) < kLinearTolerance;
}

std::string Mm(double metres) {
  char text[64];
  std::snprintf(text, sizeof text, "%.12g mm", metres * 1e3);
  return text;
}
std::string Um(double metres) {
  char text[64];
  std::snprintf(text, sizeof text, "%.12g um", metres * 1e6 + 0.0);
  return text;
}

std::string Entities(const std::vector<int>& faces) {
  std::string out;
  for (const int f : faces) out += std::string(out.empty() ? "" : ", ") + "#" + std::to_string(f);
  return out;
}

[[noreturn]] void RefusePmi(const std::string& what, int entity, const std::string& why) {
  throw UserError("import: the STEP file's " + what + " on face #" + std::to_string(entity) +
                  " is refused: " + why + "; give it in the sidecar instead (docs/cad-import.md)");
}

const char* KindName(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::kHole:
      return "hole";
    case FeatureKind::kShaft:
      return "cylinder";
    case FeatureKind::kPlane:
      return "plane";
    case FeatureKind::kCone:
      return "cone";
    case FeatureKind::kSphere:
      return "sphere";
  }
  return "?";
}

// Cylinders of one part on one axis with one radius and one side of the material, whose axial
// extents touch, are one feature; planes, cones and spheres are one feature a face.
std::vector<Feature> FindFeatures(const CadPart& part) {
  std::vector<Feature> features;
  for (const CadFace& face : part.faces) {
    Feature feature;
    feature.part = part.name;
    feature.faces = {face.entity};
    feature.origin = face.origin;
    feature.axis = face.axis;
    feature.diameter = 2.0 * face.radius;
    feature.axial_min = face.axial_min;
    feature.axial_max = face.axial_max;
    switch (face.kind) {
      case SurfaceKind::kCylinder:
        feature.kind = face.convex ? FeatureKind::kShaft : FeatureKind::kHole;
        break;
      case SurfaceKind::kPlane:
        feature.kind = FeatureKind::kPlane;
        break;
      case SurfaceKind::kCone:
        feature.kind = FeatureKind::kCone;
        break;
      case SurfaceKind::kSphere:
        feature.kind = FeatureKind::kSphere;
        break;
      default:
        continue;  // B-spline and other faces: checked against the pairs below
    }
    bool merged = false;
    if (feature.kind == FeatureKind::kHole || feature.kind == FeatureKind::kShaft) {
      for (Feature& other : features) {
        if (other.kind != feature.kind ||
            std::abs(other.diameter - feature.diameter) > kLinearTolerance ||
            !SameLine(other.origin, other.axis, feature.origin, feature.axis)) {
          continue;
        }
        // Extents in `other`'s frame along its axis.
        const double shift = Dot(Sub(feature.origin, other.origin), other.axis);
        const double sign = Dot(feature.axis, other.axis) > 0 ? 1.0 : -1.0;
        const double lo = shift + sign * (sign > 0 ? feature.axial_min : feature.axial_max);
        const double hi = shift + sign * (sign > 0 ? feature.axial_max : feature.axial_min);
        if (lo > other.axial_max + kLinearTolerance || hi < other.axial_min - kLinearTolerance) {
          continue;
        }
        other.axial_min = std::min(other.axial_min, lo);
        other.axial_max = std::max(other.axial_max, hi);
        other.faces.push_back(face.entity);
        merged = true;
        break;
      }
    }
    if (!merged) features.push_back(feature);
  }
  std::stable_sort(features.begin(), features.end(), [](const Feature& a, const Feature& b) {
    if (a.kind != b.kind) return a.kind < b.kind;
    return a.diameter < b.diameter;
  });
  std::map<FeatureKind, int> counts;
  for (Feature& feature : features) {
    feature.name =
        std::string(KindName(feature.kind)) + "-" + std::to_string(++counts[feature.kind]);
  }
  return features;
}

std::optional<std::size_t> FeatureOfFace(const std::vector<Feature>& features, int entity) {
  for (std::size_t i = 0; i < features.size(); ++i) {
    if (std::find(features[i].faces.begin(), features[i].faces.end(), entity) !=
        features[i].faces.end()) {
      return i;
    }
  }
  return std::nullopt;
}

const CadFace* FindFace(const CadDocument& document, int entity) {
  for (const CadPart& part : document.parts) {
    for (const CadFace& face : part.faces) {
      if (face.entity == entity) return &face;
    }
  }
  return nullptr;
}

std::string FormKey(ToleranceKind kind) {
  switch (kind) {
    case ToleranceKind::kRoundness:
      return "roundness";
    case ToleranceKind::kCylindricity:
      return "cylindricity";
    case ToleranceKind::kStraightness:
      return "straightness";
    case ToleranceKind::kFlatness:
      return "flatness";
    default:
      return "";
  }
}

// Every PMI value checked before it is used: the reader is known to give 0 for values it did not
// read, to drop a lower deviation's sign, and to misscale ± values of inch files.
void TakePmi(Import& import) {
  const CadDocument& document = import.document;
  const std::string unit = document.length_unit;
  const bool metric = unit.empty() || unit.find("metre") != std::string::npos ||
                      unit.find("METRE") != std::string::npos || unit == "MM" || unit == "M";
  for (const CadTolerance& tolerance : document.tolerances) {
    const std::string what = tolerance.kind == ToleranceKind::kSize
                                 ? std::string("diameter")
                                 : ToleranceKindName(tolerance.kind) + std::string(" tolerance");
    if (tolerance.kind == ToleranceKind::kOther) {
      import.ignored.push_back(tolerance.type + " on " + Entities(tolerance.faces));
      continue;
    }
    if (tolerance.faces.empty()) {
      import.ignored.push_back(what + " attached to no face");
      continue;
    }
    const int entity = tolerance.faces.front();
    const CadFace* face = FindFace(document, entity);
    if (face == nullptr) RefusePmi(what, entity, "the reader kept no such face");
    if (face->kind == SurfaceKind::kBSpline) {
      RefusePmi(what, entity,
                "the face is a " + face->surface_type +
                    " surface, not an analytic cylinder, cone, sphere or plane");
    }
    const std::optional<std::size_t> feature = FeatureOfFace(import.features, entity);
    if (!feature) RefusePmi(what, entity, "the face belongs to no feature fitfeel recognises");
    FeatureTolerances& target = import.tolerances[*feature];
    const std::string source = "STEP #" + std::to_string(entity);
    if (!metric && (tolerance.kind != ToleranceKind::kSize || tolerance.has_plus_minus ||
                    tolerance.has_range)) {
      RefusePmi(what, entity,
                "the file's length unit is " + unit +
                    " and the STEP reader does not scale tolerance values of such files "
                    "reliably");
    }
    if (tolerance.kind != ToleranceKind::kSize) {
      if (!(tolerance.value > 0.0)) RefusePmi(what, entity, "its value is " + Um(tolerance.value));
      target.form[FormKey(tolerance.kind)] = {tolerance.value, source};
      continue;
    }
    const Feature& f = import.features[*feature];
    if (!(tolerance.value > 0.0)) RefusePmi(what, entity, "its nominal size is 0");
    if (std::abs(tolerance.value - f.diameter) > 1e-6 * f.diameter) {
      RefusePmi(what, entity,
                "its nominal " + Mm(tolerance.value) + " is not the face's diameter " +
                    Mm(f.diameter) + " (a value not in the document's unit)");
    }
    Size size;
    size.nominal = tolerance.value;
    size.source = source;
    if (!tolerance.iso_class.empty()) {
      iso286::Limits limits;
      try {
        limits = iso286::Lookup(tolerance.value, tolerance.iso_class);
      } catch (const std::invalid_argument& e) {
        RefusePmi(what, entity,
                  "its ISO 286 class " + tolerance.iso_class + " is refused: " + e.what());
      }
      if (limits.is_hole != (f.kind == FeatureKind::kHole)) {
        RefusePmi(what, entity,
                  "its class " + tolerance.iso_class + " is a " +
                      (limits.is_hole ? "hole" : "shaft") + " class on a " +
                      (f.kind == FeatureKind::kHole ? "hole" : "shaft"));
      }
      size.iso_class = limits.code;
      size.lower = limits.lower_deviation;
      size.upper = limits.upper_deviation;
    } else if (tolerance.has_plus_minus || tolerance.has_range) {
      size.lower = tolerance.has_range ? tolerance.lower - tolerance.value : tolerance.lower;
      size.upper = tolerance.has_range ? tolerance.upper - tolerance.value : tolerance.upper;
      if (size.lower == 0.0 && size.upper == 0.0) {
        RefusePmi(what, entity,
                  "both deviations read as 0 (the reader gives 0 for a value it did not read)");
      }
      if (!(size.lower < size.upper)) {
        RefusePmi(what, entity,
                  "its lower deviation " + Um(size.lower) + " is not below its upper " +
                      Um(size.upper) + " (the reader may drop a lower deviation's sign)");
      }
    } else {
      continue;  // a nominal without tolerance: the sidecar must give it
    }
    target.size = size;
  }
}

// The sidecar: per part, per feature (name or "#entity"), the tolerances the CAD file lacks; a
// value the file gives as well must agree with it.
void TakeSidecar(Import& import, const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw UserError("import: cannot read the sidecar '" + file.string() + "'");
  std::stringstream text;
  text << in.rdbuf();
  const ConfigNode root = ConfigNode::Parse(text.str(), file.string());
  root.ExpectOnlyKeys({"parts", "scenario"});
  const YAML::Node raw = YAML::Load(text.str());
  if (std::optional<ConfigNode> parts = root.Find("parts")) {
    for (const std::string& part : parts->Keys()) {
      const ConfigNode node = parts->Child(part);
      node.ExpectOnlyKeys({"features", "chamfer", "texture", "material"});
      const auto known = std::find_if(import.document.parts.begin(), import.document.parts.end(),
                                      [&](const CadPart& p) { return p.name == part; });
      if (known == import.document.parts.end()) {
        std::string names;
        for (const CadPart& p : import.document.parts) names += " " + p.name;
        node.Fail("a part of the STEP file (" + names.substr(names.empty() ? 0 : 1) + ")",
                  "'" + part + "'");
      }
      for (const char* extra : {"chamfer", "texture", "material"}) {
        if (!node.Has(extra)) continue;
        if (std::string(extra) == "chamfer") node.Child(extra).AsQuantity(Dimension::kLength);
        YAML::Emitter out;
        out << YAML::Flow << raw["parts"][part][extra];
        import.part_extras[part][extra] = out.c_str();
      }
      const std::optional<ConfigNode> features = node.Find("features");
      if (!features) continue;
      for (const std::string& key : features->Keys()) {
        const ConfigNode values = features->Child(key);
        std::optional<std::size_t> index;
        for (std::size_t i = 0; i < import.features.size(); ++i) {
          const Feature& f = import.features[i];
          if (f.part != part) continue;
          if (f.name == key || (key.size() > 1 && key[0] == '#' &&
                                std::find(f.faces.begin(), f.faces.end(),
                                          std::atoi(key.c_str() + 1)) != f.faces.end())) {
            index = i;
          }
        }
        if (!index) {
          std::string names;
          for (const Feature& f : import.features) {
            if (f.part == part) names += ", " + f.name + " (" + Entities(f.faces) + ")";
          }
          features->Fail("a feature of " + part + ": " + names.substr(2), "'" + key + "'");
        }
        values.ExpectOnlyKeys({"size", "roundness", "cylindricity", "straightness", "flatness"});
        FeatureTolerances& target = import.tolerances[*index];
        const Feature& feature = import.features[*index];
        if (std::optional<ConfigNode> size_node = values.Find("size")) {
          Size size;
          size.source = "sidecar";
          if (size_node->is_map()) {
            size_node->ExpectOnlyKeys({"nominal", "lower", "upper"});
            size.nominal = size_node->Child("nominal").AsQuantity(Dimension::kLength);
            size.lower = size_node->Child("lower").AsQuantity(Dimension::kLength);
            size.upper = size_node->Child("upper").AsQuantity(Dimension::kLength);
            if (!(size.lower < size.upper)) {
              size_node->Fail("a lower deviation below the upper one", size_node->Describe());
            }
          } else {
            const std::string written = size_node->AsString();
            const std::size_t split = written.find_last_of(' ');
            if (split == std::string::npos) {
              size_node->Fail("'<nominal> <ISO 286 class>' or {nominal, lower, upper}",
                              size_node->Describe());
            }
            const ConfigNode nominal = ConfigNode::Parse("nominal: " + written.substr(0, split),
                                                         file.string(), size_node->path());
            try {
              size.nominal = nominal.Child("nominal").AsQuantity(Dimension::kLength);
              const iso286::Limits limits = iso286::Lookup(size.nominal, written.substr(split + 1));
              size.iso_class = limits.code;
              size.lower = limits.lower_deviation;
              size.upper = limits.upper_deviation;
            } catch (const std::exception& e) {
              size_node->Fail("'<nominal> <ISO 286 class>' with a class ISO 286 defines",
                              size_node->Describe() + " (" + e.what() + ")");
            }
          }
          if (std::abs(size.nominal - feature.diameter) > 1e-6 * feature.diameter) {
            size_node->Fail("the nominal size of " + feature.name + ", " + Mm(feature.diameter),
                            Mm(size.nominal));
          }
          if (target.size) {
            const Size& cad = *target.size;
            if (std::abs(cad.lower - size.lower) > 1e-9 ||
                std::abs(cad.upper - size.upper) > 1e-9) {
              size_node->Fail(
                  "the value the STEP file gives (" + cad.source + ": " +
                      (cad.iso_class.empty() ? "" : cad.iso_class + ", ") + Um(cad.lower) + " / " +
                      Um(cad.upper) + ") or none",
                  size_node->Describe() + " (" + Um(size.lower) + " / " + Um(size.upper) + ")");
            }
          } else {
            target.size = size;
          }
        }
        for (const char* form : {"roundness", "cylindricity", "straightness", "flatness"}) {
          const std::optional<ConfigNode> node_form = values.Find(form);
          if (!node_form) continue;
          const double value = node_form->AsQuantityIn(Dimension::kLength, 0.0, 1e-3, false);
          const auto cad = target.form.find(form);
          if (cad != target.form.end()) {
            if (std::abs(cad->second.first - value) > 1e-12) {
              node_form->Fail("the value the STEP file gives (" + cad->second.second + ": " +
                                  Um(cad->second.first) + ") or none",
                              node_form->Describe());
            }
          } else {
            target.form[form] = {value, "sidecar"};
          }
        }
      }
    }
  }
  if (std::optional<ConfigNode> scenario = root.Find("scenario")) {
    const std::vector<std::string_view> allowed = {"description", "moving", "model", "part_motion",
                                                   "device",      "safety", "run"};
    scenario->ExpectOnlyKeys(allowed);
    for (const std::string& key : scenario->Keys()) {
      YAML::Emitter out;
      out << raw["scenario"][key];
      import.scenario_sections.emplace_back(key, out.c_str());
    }
  }
}

// B-spline faces lying on a cylinder of another part, coaxial with it: a mating feature fitfeel
// cannot measure.
void CheckBSplines(const Import& import) {
  for (const CadPart& part : import.document.parts) {
    for (const CadFace& face : part.faces) {
      if (face.kind != SurfaceKind::kBSpline || face.samples.empty()) continue;
      for (const Feature& other : import.features) {
        if (other.part == part.name ||
            (other.kind != FeatureKind::kShaft && other.kind != FeatureKind::kHole)) {
          continue;
        }
        const double radius = other.diameter / 2.0;
        const bool on = std::all_of(face.samples.begin(), face.samples.end(), [&](const Vec& p) {
          return std::abs(FromAxis(p, other.origin, other.axis) - radius) < 1e-3 * radius;
        });
        if (on) {
          throw UserError("import: part " + part.name + ": face #" + std::to_string(face.entity) +
                          " is a " + face.surface_type + " surface where it mates with " +
                          other.part + "'s " + other.name + " (Ø" + Mm(other.diameter) +
                          "); a mating feature must be an analytic cylinder: export the part "
                          "with analytic surfaces");
        }
      }
    }
  }
}

void FindPairs(Import& import) {
  for (std::size_t h = 0; h < import.features.size(); ++h) {
    const Feature& hole = import.features[h];
    if (hole.kind != FeatureKind::kHole) continue;
    for (std::size_t s = 0; s < import.features.size(); ++s) {
      const Feature& shaft = import.features[s];
      if (shaft.kind != FeatureKind::kShaft || shaft.part == hole.part) continue;
      if (!SameLine(hole.origin, hole.axis, shaft.origin, shaft.axis)) continue;
      const auto nominal = [&](std::size_t i) {
        const auto t = import.tolerances.find(i);
        return t != import.tolerances.end() && t->second.size ? t->second.size->nominal
                                                              : import.features[i].diameter;
      };
      if (std::abs(nominal(h) - nominal(s)) > kLinearTolerance) continue;
      import.pairs.push_back({h, s});
    }
  }
}

std::string SizeText(const Size& size) {
  if (!size.iso_class.empty()) return Mm(size.nominal) + " " + size.iso_class;
  return "{nominal: " + Mm(size.nominal) + ", lower: " + Um(size.lower) +
         ", upper: " + Um(size.upper) + "}";
}

}  // namespace

Import BuildImport(CadDocument document, const std::optional<std::filesystem::path>& sidecar) {
  Import import;
  import.document = std::move(document);
  for (const CadPart& part : import.document.parts) {
    if (part.name.empty()) throw UserError("import: a part of the STEP file has no name");
    for (const CadPart& other : import.document.parts) {
      if (&other != &part && other.name == part.name) {
        throw UserError("import: two parts of the STEP file are both named '" + part.name +
                        "'; the sidecar and the scene name parts, so names must differ");
      }
    }
    std::vector<Feature> found = FindFeatures(part);
    import.features.insert(import.features.end(), found.begin(), found.end());
  }
  TakePmi(import);
  if (sidecar) TakeSidecar(import, *sidecar);
  CheckBSplines(import);
  FindPairs(import);
  return import;
}

std::string DescribeImport(const Import& import) {
  std::ostringstream out;
  out << "schema: " << import.document.schema << "\nlength unit: " << import.document.length_unit
      << "\n";
  for (const CadPart& part : import.document.parts) {
    out << "part " << part.name << " (" << part.faces.size() << " faces)\n";
    for (const std::string& datum : part.datums) out << "  datum " << datum << "\n";
    for (std::size_t i = 0; i < import.features.size(); ++i) {
      const Feature& f = import.features[i];
      if (f.part != part.name) continue;
      out << "  " << f.name << " (" << Entities(f.faces) << ")";
      if (f.kind == FeatureKind::kHole || f.kind == FeatureKind::kShaft) {
        out << ": Ø" << Mm(f.diameter) << ", length " << Mm(f.axial_max - f.axial_min);
      }
      out << "\n";
      const auto t = import.tolerances.find(i);
      if (t == import.tolerances.end()) continue;
      if (t->second.size) {
        out << "    size " << SizeText(*t->second.size) << " (" << Um(t->second.size->lower)
            << " / " << Um(t->second.size->upper) << ", from " << t->second.size->source << ")\n";
      }
      for (const auto& [key, value] : t->second.form) {
        out << "    " << key << " " << Um(value.first) << " (from " << value.second << ")\n";
      }
    }
  }
  for (const std::string& ignored : import.ignored) out << "not used: " << ignored << "\n";
  for (const Pair& pair : import.pairs) {
    const Feature& h = import.features[pair.hole];
    const Feature& s = import.features[pair.shaft];
    out << "pair: " << h.part << " " << h.name << " / " << s.part << " " << s.name << " (Ø"
        << Mm(h.diameter) << ", coaxial)\n";
  }
  if (import.pairs.empty()) out << "no mating pair found\n";
  return out.str();
}

std::string ScenarioText(const Import& import, const std::string& name,
                         const std::string& source_file) {
  if (import.pairs.empty()) {
    throw UserError(
        "import: no hole of one part and cylinder of the other share an axis and a "
        "nominal size, so there is no fit to feel");
  }
  if (import.pairs.size() > 1) {
    std::string list;
    for (const Pair& p : import.pairs) {
      list += "; " + import.features[p.hole].part + " " + import.features[p.hole].name + " / " +
              import.features[p.shaft].part + " " + import.features[p.shaft].name;
    }
    throw UserError("import: " + std::to_string(import.pairs.size()) + " mating pairs found (" +
                    list.substr(2) + "); a scene from CAD takes exactly one");
  }
  const Pair& pair = import.pairs.front();
  const auto section = [&](const std::string& key) -> std::optional<std::string> {
    for (const auto& [k, text] : import.scenario_sections) {
      if (k == key) return text;
    }
    return std::nullopt;
  };
  std::ostringstream out;
  out << "# Written by `fitfeel import` from " << source_file
      << ": the parts, sizes, tolerances and lengths\n"
      << "# come from the STEP file and its sidecar (each says which); the sections marked "
         "\"not in the CAD\n# file\" are defaults or the sidecar's, to be checked.\n";
  out << "scenario: " << name << "\n";
  out << "description: "
      << (section("description") ? *section("description")
                                 : "\"Imported from " + source_file + "\"")
      << "\n";
  out << "surface: fitfeel.surface.cylindrical\nparts:\n";
  const Feature& shaft = import.features[pair.shaft];
  const Feature& hole = import.features[pair.hole];
  for (const std::size_t index : {pair.shaft, pair.hole}) {
    const Feature& f = import.features[index];
    const bool outer = index == pair.hole;
    const auto t = import.tolerances.find(index);
    if (t == import.tolerances.end() || !t->second.size) {
      throw UserError("import: part " + f.part + ", " + f.name + " (" + Entities(f.faces) +
                      ") has no size tolerance in the STEP file; give it in the sidecar (parts: " +
                      f.part + ": features: " + f.name + ": size: ...)");
    }
    const FeatureTolerances& tol = t->second;
    const auto extras = import.part_extras.find(f.part);
    const auto extra = [&](const char* key) -> std::optional<std::string> {
      if (extras == import.part_extras.end()) return std::nullopt;
      const auto e = extras->second.find(key);
      if (e == extras->second.end()) return std::nullopt;
      return e->second;
    };
    out << "  " << f.part << ":\n    role: " << (outer ? "outer" : "inner") << "\n";
    out << "    size: " << SizeText(*tol.size) << "   # " << f.name << ", from " << tol.size->source
        << "\n";
    out << "    geometry: {length: " << Mm(f.axial_max - f.axial_min);
    if (outer) {
      // The part's largest cylinder on the bore's axis is its outside.
      double outside = 0.0;
      for (const Feature& other : import.features) {
        if (other.part == f.part && other.kind == FeatureKind::kShaft &&
            SameLine(other.origin, other.axis, f.origin, f.axis)) {
          outside = std::max(outside, other.diameter);
        }
      }
      if (outside <= f.diameter) {
        throw UserError("import: part " + f.part + " has no outer cylinder on the axis of " +
                        f.name + "; the cylindrical surface needs the outer diameter");
      }
      out << ", outer_diameter: " << Mm(outside);
    }
    if (extra("chamfer")) out << ", chamfer: " << *extra("chamfer");
    out << "}   # lengths from STEP" << (extra("chamfer") ? ", chamfer from the sidecar" : "")
        << "\n";
    bool form_open = false;
    for (const auto& [key, value] : tol.form) {
      std::string scenario_key = key == "straightness" ? "axis_straightness" : key;
      if (key == "flatness") continue;  // a plane's, not the cylinder's
      if (!form_open) out << "    form:\n";
      form_open = true;
      out << "      " << scenario_key << ": " << Um(value.first) << "   # from " << value.second
          << "\n";
    }
    if (extra("texture")) out << "    texture: " << *extra("texture") << "   # from the sidecar\n";
    if (extra("material")) {
      out << "    material: " << *extra("material") << "   # from the sidecar\n";
    } else {
      out << "    material: {name: steel, youngs_modulus: 210 GPa, poisson: 0.3}   # not in the "
             "CAD file: assumed\n";
    }
  }
  const auto write_section = [&](const std::string& key, const std::string& fallback) {
    const std::optional<std::string> given = section(key);
    if (given) {
      std::string text = *given;
      std::string indented;
      std::istringstream lines(text);
      std::string line;
      bool scalar = text.find('\n') == std::string::npos && text.find(':') == std::string::npos;
      if (scalar) {
        out << key << ": " << text << "   # from the sidecar\n";
        return;
      }
      out << key << ":   # from the sidecar\n";
      while (std::getline(lines, line)) out << "  " << line << "\n";
    } else if (!fallback.empty()) {
      out << key << ": " << fallback << "   # not in the CAD file: a default\n";
    }
  };
  write_section("moving", shaft.part);
  const double travel = shaft.axial_max - shaft.axial_min;
  write_section("model", "{law: elastic, friction: 0.15, contact_stiffness: auto}");
  write_section("part_motion", "");
  write_section("device", "{plugin: fitfeel.device.simulated, speed: 10 mm/s}");
  write_section("safety", "");
  char run[160];
  std::snprintf(run, sizeof run,
                "{rate: 1000 Hz, duration: %.12g s, seed: 1, clock: virtual, outputs: [trace, "
                "summary]}",
                travel / 0.01);
  write_section("run", run);
  (void)hole;
  return out.str();
}

}  // namespace fitfeel::cad
