#include "framework/cad/import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
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
    case FeatureKind::kTaperHole:
      return "taper-hole";
    case FeatureKind::kCone:
      return "cone";
    case FeatureKind::kSeat:
      return "seat";
    case FeatureKind::kSphere:
      return "sphere";
    case FeatureKind::kPlane:
      return "plane";
  }
  return "?";
}

bool Concave(FeatureKind kind) {
  return kind == FeatureKind::kHole || kind == FeatureKind::kTaperHole ||
         kind == FeatureKind::kSeat;
}

// The convex kind a concave one mates with.
FeatureKind MateOf(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::kHole:
      return FeatureKind::kShaft;
    case FeatureKind::kTaperHole:
      return FeatureKind::kCone;
    case FeatureKind::kSeat:
      return FeatureKind::kSphere;
    default:
      return FeatureKind::kPlane;
  }
}

// A feature on `f`'s axis seen in `f`'s frame: its radius at f's origin, its slope along f's
// axis and its axial extent there.
struct Along {
  double radius = 0.0;
  double slope = 0.0;
  double lo = 0.0;
  double hi = 0.0;
};
Along InFrameOf(const Feature& g, const Feature& f) {
  const double sign = Dot(g.axis, f.axis) > 0 ? 1.0 : -1.0;
  const double shift = Dot(Sub(g.origin, f.origin), f.axis);
  Along a;
  a.slope = sign * g.slope;
  a.radius = g.ref_radius - g.slope * sign * shift;
  a.lo = shift + (sign > 0 ? g.axial_min : -g.axial_max);
  a.hi = shift + (sign > 0 ? g.axial_max : -g.axial_min);
  return a;
}

double Distance(const Vec& a, const Vec& b) {
  const Vec d = Sub(a, b);
  return std::sqrt(Dot(d, d));
}

// Where a feature lies, for naming features of one size in a fixed order: the point of its axis
// nearest the frame's origin (a sphere's centre, a plane's foot of the perpendicular).
Vec PlaceOf(const Feature& f) {
  if (f.kind == FeatureKind::kSeat || f.kind == FeatureKind::kSphere) return f.origin;
  const double along = Dot(f.origin, f.axis);
  if (f.kind == FeatureKind::kPlane)
    return {along * f.axis[0], along * f.axis[1], along * f.axis[2]};
  return Sub(f.origin, {along * f.axis[0], along * f.axis[1], along * f.axis[2]});
}

// Faces of one part on one surface (a cylinder or cone on one axis with one radius and taper, a
// sphere with one centre and radius), on one side of the material, whose extents touch, are one
// feature; a plane is one feature a face.
std::vector<Feature> FindFeatures(const CadPart& part) {
  std::vector<Feature> features;
  for (const CadFace& face : part.faces) {
    Feature feature;
    feature.part = part.name;
    feature.faces = {face.entity};
    feature.origin = face.origin;
    feature.axis = face.axis;
    feature.ref_radius = face.radius;
    feature.axial_min = face.axial_min;
    feature.axial_max = face.axial_max;
    switch (face.kind) {
      case SurfaceKind::kCylinder:
        feature.kind = face.convex ? FeatureKind::kShaft : FeatureKind::kHole;
        break;
      case SurfaceKind::kCone:
        feature.kind = face.convex ? FeatureKind::kCone : FeatureKind::kTaperHole;
        feature.slope = std::tan(face.semi_angle);
        break;
      case SurfaceKind::kSphere:
        feature.kind = face.convex ? FeatureKind::kSphere : FeatureKind::kSeat;
        break;
      case SurfaceKind::kPlane:
        feature.kind = FeatureKind::kPlane;
        break;
      default:
        continue;  // B-spline and other faces: checked against the pairs below
    }
    bool merged = false;
    for (Feature& other : features) {
      if (other.kind != feature.kind || feature.kind == FeatureKind::kPlane) continue;
      const bool sphere =
          feature.kind == FeatureKind::kSeat || feature.kind == FeatureKind::kSphere;
      if (sphere ? Distance(other.origin, feature.origin) > kLinearTolerance ||
                       std::abs(std::abs(Dot(other.axis, feature.axis)) - 1.0) > kAngularTolerance
                 : !SameLine(other.origin, other.axis, feature.origin, feature.axis)) {
        continue;
      }
      const Along a = InFrameOf(feature, other);
      if (std::abs(a.radius - other.ref_radius) > kLinearTolerance ||
          std::abs(a.slope - other.slope) > kAngularTolerance) {
        continue;
      }
      if (a.lo > other.axial_max + kLinearTolerance || a.hi < other.axial_min - kLinearTolerance) {
        continue;
      }
      other.axial_min = std::min(other.axial_min, a.lo);
      other.axial_max = std::max(other.axial_max, a.hi);
      other.faces.push_back(face.entity);
      merged = true;
      break;
    }
    if (!merged) features.push_back(feature);
  }
  for (Feature& f : features) {
    const double r0 = f.ref_radius + f.slope * f.axial_min;
    const double r1 = f.ref_radius + f.slope * f.axial_max;
    f.diameter = 2.0 * std::min(r0, r1);
    f.large_diameter = 2.0 * std::max(r0, r1);
  }
  std::stable_sort(features.begin(), features.end(), [](const Feature& a, const Feature& b) {
    if (a.kind != b.kind) return a.kind < b.kind;
    if (std::abs(a.diameter - b.diameter) > kLinearTolerance) return a.diameter < b.diameter;
    const Vec pa = PlaceOf(a), pb = PlaceOf(b);
    for (int i = 0; i < 3; ++i) {
      if (std::abs(pa[i] - pb[i]) > kLinearTolerance) return pa[i] < pb[i];
    }
    return false;
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

// The scenario's form key of a form tolerance (its name); empty for a size or an unknown kind.
std::string FormKey(ToleranceKind kind) {
  return kind == ToleranceKind::kSize || kind == ToleranceKind::kOther ? ""
                                                                       : ToleranceKindName(kind);
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
      if (limits.is_hole != Concave(f.kind)) {
        RefusePmi(what, entity,
                  "its class " + tolerance.iso_class + " is a " +
                      (limits.is_hole ? "hole" : "shaft") + " class on a " +
                      (Concave(f.kind) ? "hole" : "shaft"));
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
        values.ExpectOnlyKeys({"size", "roundness", "cylindricity", "straightness", "flatness",
                               "sphericity", "generatrix_straightness", "outer_diameter",
                               "position"});
        FeatureSettings& settings = import.settings[*index];
        if (std::optional<ConfigNode> outer = values.Find("outer_diameter")) {
          settings.outer_diameter = outer->AsQuantityIn(Dimension::kLength, 0.0, 10.0, false);
          if (!(*settings.outer_diameter > import.features[*index].large_diameter)) {
            outer->Fail(
                "a diameter above the feature's, " + Mm(import.features[*index].large_diameter),
                outer->Describe());
          }
        }
        if (std::optional<ConfigNode> position = values.Find("position")) {
          settings.position = position->AsQuantityIn(Dimension::kLength, 0.0, 1e-3);
        }
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
        for (const char* form : {"roundness", "cylindricity", "straightness", "flatness",
                                 "sphericity", "generatrix_straightness"}) {
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
  const auto nominal = [&](std::size_t i) {
    const auto t = import.tolerances.find(i);
    return t != import.tolerances.end() && t->second.size ? t->second.size->nominal
                                                          : import.features[i].diameter;
  };
  for (std::size_t h = 0; h < import.features.size(); ++h) {
    const Feature& hole = import.features[h];
    if (!Concave(hole.kind)) continue;
    for (std::size_t s = 0; s < import.features.size(); ++s) {
      const Feature& shaft = import.features[s];
      if (shaft.kind != MateOf(hole.kind) || shaft.part == hole.part) continue;
      if (hole.kind == FeatureKind::kSeat) {
        // A captive ball: one centre, and the bands about one axis.
        if (Distance(hole.origin, shaft.origin) > kLinearTolerance ||
            std::abs(std::abs(Dot(hole.axis, shaft.axis)) - 1.0) > kAngularTolerance) {
          continue;
        }
      } else {
        if (!SameLine(hole.origin, hole.axis, shaft.origin, shaft.axis)) continue;
        // One taper, its small end the same way: the cone enters the hole's large end.
        if (std::abs(InFrameOf(shaft, hole).slope - hole.slope) > kAngularTolerance) continue;
      }
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

enum class Surface { kCylindrical, kConical, kSpherical };

Surface SurfaceOf(const Import& import, const Pair& pair) {
  switch (import.features[pair.hole].kind) {
    case FeatureKind::kTaperHole:
      return Surface::kConical;
    case FeatureKind::kSeat:
      return Surface::kSpherical;
    default:
      return Surface::kCylindrical;
  }
}

const char* PluginOf(Surface surface) {
  switch (surface) {
    case Surface::kConical:
      return "fitfeel.surface.conical";
    case Surface::kSpherical:
      return "fitfeel.surface.spherical";
    default:
      return "fitfeel.surface.cylindrical";
  }
}

// "1:50" when the taper is one over a whole number, else C = 2 tan(alpha) as a number.
std::string TaperText(double slope) {
  const double c = 2.0 * std::abs(slope);
  const double n = 1.0 / c;
  char text[64];
  if (std::abs(n - std::round(n)) < 1e-6 * n) {
    std::snprintf(text, sizeof text, "\"1:%.0f\"", std::round(n));
  } else {
    std::snprintf(text, sizeof text, "%.12g", c);
  }
  return text;
}

std::string PairText(const Import& import, const Pair& pair) {
  const Feature& h = import.features[pair.hole];
  const Feature& s = import.features[pair.shaft];
  std::string text = h.part + " " + h.name + " / " + s.part + " " + s.name + " (Ø" + Mm(h.diameter);
  if (h.kind == FeatureKind::kTaperHole) {
    text += " at the small end, taper " + TaperText(h.slope) + ", coaxial)";
  } else if (h.kind == FeatureKind::kSeat) {
    text += ", concentric)";
  } else {
    text += ", coaxial)";
  }
  return text;
}

// The pairs as one several-feature scene (docs/assemblies.md): the datum first, each feature's
// axis in the joint frame and how far the joint advances before it engages.
struct Joint {
  std::vector<std::size_t> order;  // pair indices
  std::vector<double> engages_after;
  std::vector<std::array<double, 2>> at;  // x, z
};

// The joint of all pairs, or why they form none.
std::optional<Joint> JointOf(const Import& import, std::string* why) {
  const std::vector<Pair>& pairs = import.pairs;
  const auto parts = [&](const Pair& p) {
    std::array<std::string, 2> names{import.features[p.hole].part, import.features[p.shaft].part};
    std::sort(names.begin(), names.end());
    return names;
  };
  const Feature& datum_hole = import.features[pairs.front().hole];
  const Vec& axis = datum_hole.axis;
  std::vector<double> gaps;
  int direction = 0;
  for (const Pair& pair : pairs) {
    if (SurfaceOf(import, pair) == Surface::kSpherical) {
      *why =
          "a ball in its seat turns about its centre, and a scene of several features slides "
          "along one axis";
      return std::nullopt;
    }
    if (parts(pair) != parts(pairs.front())) {
      *why = "they join different parts, and a scene of several features joins two";
      return std::nullopt;
    }
    const Feature& hole = import.features[pair.hole];
    const Feature& shaft = import.features[pair.shaft];
    if (std::abs(std::abs(Dot(hole.axis, axis)) - 1.0) > kAngularTolerance) {
      *why = "their axes are not parallel, and a scene of several features advances along one";
      return std::nullopt;
    }
    const Along h = InFrameOf(hole, datum_hole);
    const Along s = InFrameOf(shaft, datum_hole);
    // The inner part moves towards the hole's side it lies on.
    const int d = (s.lo + s.hi) > (h.lo + h.hi) ? -1 : 1;
    if (direction != 0 && d != direction) {
      *why = "their parts meet from opposite sides";
      return std::nullopt;
    }
    direction = d;
    gaps.push_back(d > 0 ? h.lo - s.hi : s.lo - h.hi);
  }
  Joint joint;
  std::size_t datum = 0;
  for (std::size_t i = 1; i < pairs.size(); ++i) {
    if (gaps[i] < gaps[datum] - kLinearTolerance) datum = i;
  }
  joint.order.push_back(datum);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (i != datum) joint.order.push_back(i);
  }
  const Vec y = {direction * axis[0], direction * axis[1], direction * axis[2]};
  const Vec base = PlaceOf(import.features[pairs[datum].hole]);
  const auto across = [&](std::size_t i) {
    const Vec v = Sub(PlaceOf(import.features[pairs[i].hole]), base);
    const double along = Dot(v, y);
    return Vec{v[0] - along * y[0], v[1] - along * y[1], v[2] - along * y[2]};
  };
  // x towards the second feature, as a drawing dimensions the pitch; z = x × y.
  Vec x{};
  for (std::size_t i : joint.order) {
    const Vec v = across(i);
    const double length = std::sqrt(Dot(v, v));
    if (length > kLinearTolerance) {
      x = {v[0] / length, v[1] / length, v[2] / length};
      break;
    }
  }
  if (Dot(x, x) == 0.0) {
    const Vec any = std::abs(y[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
    const double along = Dot(any, y);
    x = {any[0] - along * y[0], any[1] - along * y[1], any[2] - along * y[2]};
    const double length = std::sqrt(Dot(x, x));
    x = {x[0] / length, x[1] / length, x[2] / length};
  }
  const Vec z = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  for (std::size_t i : joint.order) {
    joint.engages_after.push_back(std::max(0.0, gaps[i] - gaps[datum]));
    const Vec v = across(i);
    joint.at.push_back({Dot(v, x), Dot(v, z)});
  }
  return joint;
}

// What a feature's own sidecar lines and extras give.
class SceneWriter {
 public:
  SceneWriter(const Import& import, std::ostream& out) : import_(import), out_(out) {}

  std::optional<std::string> Extra(const std::string& part, const char* key) const {
    const auto extras = import_.part_extras.find(part);
    if (extras == import_.part_extras.end()) return std::nullopt;
    const auto e = extras->second.find(key);
    if (e == extras->second.end()) return std::nullopt;
    return e->second;
  }

  // The outer part's diameter round `f`: the sidecar's, or its largest cylinder on f's axis.
  std::pair<double, std::string> OuterDiameter(std::size_t index, Surface surface) const {
    const Feature& f = import_.features[index];
    const auto settings = import_.settings.find(index);
    if (settings != import_.settings.end() && settings->second.outer_diameter) {
      return {*settings->second.outer_diameter, "the sidecar"};
    }
    double outside = 0.0;
    for (const Feature& other : import_.features) {
      if (other.part == f.part && other.kind == FeatureKind::kShaft &&
          SameLine(other.origin, other.axis, f.origin, f.axis)) {
        outside = std::max(outside, other.diameter);
      }
    }
    if (outside <= f.large_diameter) {
      throw UserError("import: part " + f.part + " has no outer cylinder on the axis of " + f.name +
                      "; the " + std::string(PluginOf(surface)) +
                      " surface needs the outer diameter: give it in the sidecar (parts: " +
                      f.part + ": features: " + f.name + ": outer_diameter: ...)");
    }
    return {outside, "STEP"};
  }

  // One part's map in a feature: `indent` is the part key's.
  // One part's keys in a scene of `surface`, with where each value comes from.
  struct PartLines {
    std::string size;
    std::string size_source;
    std::vector<std::pair<std::string, std::string>> geometry;
    std::string geometry_sources;
    std::vector<std::array<std::string, 3>> form;  // key, value, source
    std::vector<std::string> not_written;          // tolerances the surface does not model
    std::optional<std::string> texture;
    std::optional<std::string> material;
  };

  PartLines Lines(std::size_t index, bool outer, Surface surface) const {
    const Feature& f = import_.features[index];
    const auto t = import_.tolerances.find(index);
    if (t == import_.tolerances.end() || !t->second.size) {
      throw UserError("import: part " + f.part + ", " + f.name + " (" + Entities(f.faces) +
                      ") has no size tolerance in the STEP file; give it in the sidecar (parts: " +
                      f.part + ": features: " + f.name + ": size: ...)");
    }
    const FeatureTolerances& tol = t->second;
    PartLines lines;
    lines.size = SizeText(*tol.size);
    lines.size_source = f.name + ", from " + tol.size->source;
    const double length = f.axial_max - f.axial_min;
    lines.geometry_sources = "STEP";
    const auto outer_diameter = [&] {
      const auto [d, from] = OuterDiameter(index, surface);
      lines.geometry.emplace_back("outer_diameter", Mm(d));
      if (from != "STEP") lines.geometry_sources += ", outer diameter from " + from;
    };
    if (surface == Surface::kSpherical) {
      lines.geometry.emplace_back("width", Mm(length));
      if (outer) {
        outer_diameter();
      } else {
        // The inner ring's bore: its largest hole on the band's axis, inside the sphere.
        double bore = 0.0;
        for (const Feature& other : import_.features) {
          if (other.part == f.part && other.kind == FeatureKind::kHole &&
              other.diameter < f.diameter && SameLine(other.origin, other.axis, f.origin, f.axis)) {
            bore = std::max(bore, other.diameter);
          }
        }
        if (bore > 0.0) lines.geometry.emplace_back("bore_diameter", Mm(bore));
      }
    } else {
      lines.geometry.emplace_back("length", Mm(length));
      if (surface == Surface::kConical) lines.geometry.emplace_back("taper", TaperText(f.slope));
      if (outer) outer_diameter();
      if (Extra(f.part, "chamfer")) {
        lines.geometry.emplace_back("chamfer", *Extra(f.part, "chamfer"));
        lines.geometry_sources += ", chamfer from the sidecar";
      }
    }
    // The characteristics each surface models, by the PMI's or sidecar's names.
    std::map<std::string, std::string> keys;
    switch (surface) {
      case Surface::kCylindrical:
        keys = {{"roundness", "roundness"},
                {"cylindricity", "cylindricity"},
                {"straightness", "axis_straightness"},
                {"generatrix_straightness", "generatrix_straightness"}};
        break;
      case Surface::kConical:
        keys = {{"roundness", "roundness"},
                {"straightness", "axis_straightness"},
                {"generatrix_straightness", "generatrix_straightness"}};
        break;
      case Surface::kSpherical:
        keys = {{"roundness", "roundness"}, {"sphericity", "sphericity"}};
        break;
    }
    for (const auto& [key, value] : tol.form) {
      const auto k = keys.find(key);
      if (k == keys.end()) {
        lines.not_written.push_back(key + " " + Um(value.first) + " (from " + value.second +
                                    ") is not written: " + PluginOf(surface) +
                                    " models no such tolerance");
      } else {
        lines.form.push_back({k->second, Um(value.first), value.second});
      }
    }
    lines.texture = Extra(f.part, "texture");
    lines.material = Extra(f.part, "material");
    return lines;
  }

  // One part's map in a feature: `indent` is the part key's.
  void Part(std::size_t index, bool outer, Surface surface, const std::string& indent) {
    const Feature& f = import_.features[index];
    const std::string in = indent + "  ";
    const PartLines lines = Lines(index, outer, surface);
    out_ << indent << f.part << ":\n" << in << "role: " << (outer ? "outer" : "inner") << "\n";
    out_ << in << "size: " << lines.size << "   # " << lines.size_source << "\n";
    out_ << in << "geometry: {";
    for (std::size_t i = 0; i < lines.geometry.size(); ++i) {
      out_ << (i == 0 ? "" : ", ") << lines.geometry[i].first << ": " << lines.geometry[i].second;
    }
    out_ << "}   # lengths from " << lines.geometry_sources << "\n";
    for (const std::string& note : lines.not_written) out_ << in << "# " << note << "\n";
    if (!lines.form.empty()) out_ << in << "form:\n";
    for (const auto& [key, value, source] : lines.form) {
      out_ << in << "  " << key << ": " << value << "   # from " << source << "\n";
    }
    if (lines.texture) out_ << in << "texture: " << *lines.texture << "   # from the sidecar\n";
    if (lines.material) {
      out_ << in << "material: " << *lines.material << "   # from the sidecar\n";
    } else {
      out_ << in
           << "material: {name: steel, youngs_modulus: 210 GPa, poisson: 0.3}   # not in the "
              "CAD file: assumed\n";
    }
  }

  void WritePair(const Pair& pair, const std::string& indent) {
    const Surface surface = SurfaceOf(import_, pair);
    Part(pair.shaft, false, surface, indent);
    Part(pair.hole, true, surface, indent);
  }

  std::optional<std::string> Section(const std::string& key) const {
    for (const auto& [k, text] : import_.scenario_sections) {
      if (k == key) return text;
    }
    return std::nullopt;
  }

  void WriteSection(const std::string& key, const std::string& fallback) {
    const std::optional<std::string> given = Section(key);
    if (given) {
      const bool scalar =
          given->find('\n') == std::string::npos && given->find(':') == std::string::npos;
      if (scalar) {
        out_ << key << ": " << *given << "   # from the sidecar\n";
        return;
      }
      out_ << key << ":   # from the sidecar\n";
      std::istringstream lines(*given);
      std::string line;
      while (std::getline(lines, line)) out_ << "  " << line << "\n";
    } else if (!fallback.empty()) {
      out_ << key << ": " << fallback << "   # not in the CAD file: a default\n";
    }
  }

 private:
  const Import& import_;
  std::ostream& out_;
};

std::string DefaultModel(Surface surface) {
  return surface == Surface::kCylindrical
             ? "{law: elastic, friction: 0.15, contact_stiffness: auto}"
             : "{law: gps, friction: 0.15, contact_stiffness: auto}";
}

constexpr double kDefaultSpeed = 10e-3;  // m/s, the paper's assembly speed

// How far the inner part travels in a default run: a shaft its length, a taper pin to a
// millimetre past its nominal seat.
double Travel(const Import& import, const Pair& pair) {
  const Feature& hole = import.features[pair.hole];
  const Feature& shaft = import.features[pair.shaft];
  if (hole.kind == FeatureKind::kTaperHole) return hole.axial_max - hole.axial_min + 1e-3;
  return shaft.axial_max - shaft.axial_min;
}

std::string RunText(double duration) {
  char run[160];
  std::snprintf(run, sizeof run,
                "{rate: 1000 Hz, duration: %.12g s, seed: 1, clock: virtual, outputs: [trace, "
                "summary]}",
                duration);
  return run;
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
      const double length = f.axial_max - f.axial_min;
      switch (f.kind) {
        case FeatureKind::kHole:
        case FeatureKind::kShaft:
          out << ": Ø" << Mm(f.diameter) << ", length " << Mm(length);
          break;
        case FeatureKind::kTaperHole:
        case FeatureKind::kCone:
          out << ": Ø" << Mm(f.diameter) << " at the small end, Ø" << Mm(f.large_diameter)
              << " at the large end, taper " << TaperText(f.slope) << ", length " << Mm(length);
          break;
        case FeatureKind::kSeat:
        case FeatureKind::kSphere:
          out << ": Ø" << Mm(f.diameter) << ", band " << Mm(length);
          break;
        case FeatureKind::kPlane:
          out << ": normal (" << f.axis[0] + 0.0 << ", " << f.axis[1] + 0.0 << ", "
              << f.axis[2] + 0.0 << "), " << Mm(Dot(f.origin, f.axis) + 0.0) << " from the origin";
          break;
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
  for (std::size_t i = 0; i < import.pairs.size(); ++i) {
    out << "pair " << i + 1 << ": " << PairText(import, import.pairs[i]) << "\n";
  }
  if (import.pairs.empty()) {
    out << "no mating pair found\n";
  } else if (import.pairs.size() > 1) {
    std::string why;
    if (JointOf(import, &why)) {
      out << "scene: the " << import.pairs.size()
          << " pairs as the features of one joint (docs/assemblies.md)\n";
    } else {
      out << "scene: one per pair, with --pair N: the pairs form no joint (" << why << ")\n";
    }
  }
  return out.str();
}

scenario::CadPartKeys PartKeys(const Import& import, std::size_t feature, bool outer) {
  Surface surface = Surface::kCylindrical;
  switch (import.features[feature].kind) {
    case FeatureKind::kTaperHole:
    case FeatureKind::kCone:
      surface = Surface::kConical;
      break;
    case FeatureKind::kSeat:
    case FeatureKind::kSphere:
      surface = Surface::kSpherical;
      break;
    case FeatureKind::kPlane:
      throw UserError("import: a plane is no feature a surface of fitfeel takes alone");
    default:
      break;
  }
  std::ostringstream unused;
  const SceneWriter writer(import, unused);
  const SceneWriter::PartLines lines = writer.Lines(feature, outer, surface);
  scenario::CadPartKeys keys;
  keys.size = lines.size;
  keys.geometry = lines.geometry;
  for (const auto& [key, value, source] : lines.form) keys.form.emplace_back(key, value);
  keys.texture = lines.texture;
  keys.material = lines.material;
  return keys;
}

std::string ScenarioText(const Import& import, const std::string& name,
                         const std::string& source_file, std::optional<std::size_t> pair) {
  if (import.pairs.empty()) {
    throw UserError(
        "import: no concave feature of one part and convex one of another share an axis (or a "
        "centre) and a nominal size, so there is no fit to feel");
  }
  if (pair && *pair >= import.pairs.size()) {
    throw UserError("import: --pair " + std::to_string(*pair + 1) + " names no pair: there are " +
                    std::to_string(import.pairs.size()));
  }
  std::optional<Joint> joint;
  if (!pair && import.pairs.size() > 1) {
    std::string why;
    joint = JointOf(import, &why);
    if (!joint) {
      std::string list;
      for (std::size_t i = 0; i < import.pairs.size(); ++i) {
        list += "; " + std::to_string(i + 1) + ": " + PairText(import, import.pairs[i]);
      }
      throw UserError("import: " + std::to_string(import.pairs.size()) + " mating pairs (" +
                      list.substr(2) + ") form no scene of several features: " + why +
                      "; write one scenario per pair with --pair N");
    }
  }
  std::ostringstream out;
  SceneWriter writer(import, out);
  out << "# Written by `fitfeel import` from " << source_file
      << ": the parts, sizes, tolerances and lengths\n"
      << "# come from the STEP file and its sidecar (each says which); the sections marked "
         "\"not in the CAD\n# file\" are defaults or the sidecar's, to be checked.\n";
  out << "scenario: " << name << "\n";
  out << "description: "
      << (writer.Section("description") ? *writer.Section("description")
                                        : "\"Imported from " + source_file + "\"")
      << "\n";
  if (!joint) {
    const Pair& p = import.pairs[pair.value_or(0)];
    const Surface surface = SurfaceOf(import, p);
    out << "surface: " << PluginOf(surface) << "\nparts:\n";
    writer.WritePair(p, "  ");
    writer.WriteSection("moving", import.features[p.shaft].part);
    writer.WriteSection("model", DefaultModel(surface));
    writer.WriteSection("part_motion", "");
    if (surface == Surface::kSpherical) {
      // A captive ball is turned, not pushed: a rotary drive's swing of ±15 deg, one in 4 s.
      writer.WriteSection(
          "device",
          "{plugin: fitfeel.device.simulated, mode: constant_rotation, angular_speed: "
          "15 deg/s, swing: 15 deg}");
      writer.WriteSection("safety", "");
      writer.WriteSection("run", RunText(4.0));
    } else {
      writer.WriteSection("device", "{plugin: fitfeel.device.simulated, speed: 10 mm/s}");
      writer.WriteSection("safety", "");
      writer.WriteSection("run", RunText(Travel(import, p) / kDefaultSpeed));
    }
    return out.str();
  }
  const Pair& datum = import.pairs[joint->order.front()];
  writer.WriteSection("moving", import.features[datum.shaft].part);
  bool one_surface = true;
  for (const Pair& p : import.pairs) {
    one_surface = one_surface && SurfaceOf(import, p) == SurfaceOf(import, datum);
  }
  const bool own_models = !one_surface && !writer.Section("model");
  if (!own_models) writer.WriteSection("model", DefaultModel(SurfaceOf(import, datum)));
  out << "features:\n";
  std::set<std::string> names;
  double duration = 0.0;
  for (std::size_t k = 0; k < joint->order.size(); ++k) {
    const Pair& p = import.pairs[joint->order[k]];
    const Feature& hole = import.features[p.hole];
    std::string feature = hole.name;
    if (!names.insert(feature).second) {
      feature = hole.part + "-" + hole.name;
      names.insert(feature);
    }
    const Surface surface = SurfaceOf(import, p);
    out << "  " << feature << ":   # " << PairText(import, p)
        << (k == 0 ? ", the datum: the first to engage" : "") << "\n";
    out << "    surface: " << PluginOf(surface) << "\n";
    if (own_models) {
      out << "    model: " << DefaultModel(surface) << "   # not in the CAD file: a default\n";
    }
    if (k > 0) {
      out << "    at: {x: " << Mm(joint->at[k][0]) << ", z: " << Mm(joint->at[k][1])
          << "}   # its axis from the datum's, from STEP\n";
      if (joint->engages_after[k] > kLinearTolerance) {
        out << "    engages_after: " << Mm(joint->engages_after[k]) << "   # from STEP\n";
      }
    }
    std::string positions;
    for (const std::size_t index : {p.shaft, p.hole}) {
      const auto settings = import.settings.find(index);
      if (settings == import.settings.end() || !settings->second.position) continue;
      if (k == 0) {
        throw UserError("import: the sidecar gives a position tolerance to " +
                        import.features[index].part + "'s " + import.features[index].name +
                        ", of the datum feature (" + PairText(import, p) +
                        "), which places the others and has none");
      }
      positions += std::string(positions.empty() ? "" : ", ") + import.features[index].part + ": " +
                   Um(*settings->second.position);
    }
    if (!positions.empty()) out << "    position: {" << positions << "}   # from the sidecar\n";
    out << "    parts:\n";
    writer.WritePair(p, "      ");
    duration = std::max(duration, (joint->engages_after[k] + Travel(import, p)) / kDefaultSpeed);
  }
  writer.WriteSection("part_motion", "");
  writer.WriteSection("device", "{plugin: fitfeel.device.simulated, speed: 10 mm/s}");
  writer.WriteSection("safety", "");
  writer.WriteSection("run", RunText(duration));
  return out.str();
}

}  // namespace fitfeel::cad
