#include "framework/scenario/part_parser.h"

#include <cctype>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "framework/core/quantity_parse.h"
#include "framework/iso286/iso286.h"
#include "framework/iso965/iso965.h"
#include "framework/model/measured_surface.h"
#include "framework/scenario/measurement_file.h"

namespace fitfeel::scenario {
namespace {

const char* const kSizeForms =
    "a size as '<nominal> <ISO 286 class>' (e.g. '20 mm H7', '20 mm g6'), an ISO thread "
    "designation (e.g. 'M10x1.5 6g', 'M10 6H') or a map {nominal, lower, upper} of deviations";

// Letters then grade digits, as ISO 286 writes a tolerance class: H7, g6, js6, ZC11, IT is not a
// class. Anything else in that position is not a code, so the message can say so.
bool LooksLikeIsoClass(const std::string& text) {
  std::size_t i = 0;
  while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) ++i;
  const std::size_t letters = i;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  const std::size_t digits = i - letters;
  return i == text.size() && letters >= 1 && letters <= 2 && digits >= 1 && digits <= 2;
}

SizeSpec ParseIsoSize(const ConfigNode& node, Role role) {
  const std::string text = node.AsString();
  const std::size_t end = text.find_last_not_of(" \t");
  const std::size_t split = end == std::string::npos ? end : text.find_last_of(" \t", end);
  if (split == std::string::npos) node.Fail(kSizeForms, node.Describe());
  const std::string code = text.substr(split + 1, end - split);
  const std::string nominal_text = text.substr(0, split);
  if (!LooksLikeIsoClass(code)) {
    node.Fail(kSizeForms, node.Describe() + " ('" + code + "' is not an ISO 286 tolerance class)");
  }
  const internal::QuantityParse nominal =
      internal::TryParseQuantity(nominal_text, Dimension::kLength);
  if (!nominal.problem.empty()) {
    node.Fail(kSizeForms, node.Describe() + ": the nominal size " + nominal.problem);
  }
  if (!(nominal.value > 0.0)) {
    node.Fail("a positive nominal size", node.Describe());
  }
  iso286::Limits found;
  try {
    found = iso286::Lookup(nominal.value, code);
  } catch (const std::invalid_argument& e) {
    node.Fail("an ISO 286 tolerance class defined at this nominal size",
              node.Describe() + " (" + e.what() + ")");
  }
  if (found.is_hole != (role == Role::kOuter)) {
    node.Fail(
        role == Role::kOuter
            ? "a hole tolerance class (upper-case letter, e.g. H7) for an outer part"
            : "a shaft tolerance class (lower-case letter, e.g. g6, js6) for an inner part",
        node.Describe() + " (" + code + " is a " + (found.is_hole ? "hole" : "shaft") + " class)");
  }
  SizeSpec size;
  size.nominal = found.nominal;
  size.lower_deviation = found.lower_deviation;
  size.upper_deviation = found.upper_deviation;
  size.iso_code = found.code.empty() ? code : found.code;
  return size;
}

// `size: M10x1.5 6g`: nominal d and the pitch diameter's deviations, the crest's beside them.
SizeSpec ParseThreadSize(const ConfigNode& node, Role role) {
  const std::string text = node.AsString();
  iso965::ThreadLimits found;
  try {
    found = iso965::Lookup(iso965::ParseDesignation(text));
  } catch (const UserError& e) {
    node.Fail(
        "an ISO metric thread designation of ISO 261 and ISO 965-1 (e.g. 'M10x1.5 6g', "
        "'M10 6H')",
        node.Describe() + " (" + e.what() + ")");
  }
  const iso965::ThreadDesignation& designation = found.designation;
  if (designation.internal != (role == Role::kOuter)) {
    node.Fail(role == Role::kOuter
                  ? "an internal thread class (position G or H, e.g. 6H) for an outer part"
                  : "an external thread class (position e, f, g or h, e.g. 6g) for an inner part",
              node.Describe() + " (" + designation.tolerance_class + " is an " +
                  (designation.internal ? "internal" : "external") + " thread class)");
  }
  const iso965::DiameterLimits& crest = designation.internal ? found.minor : found.major;
  SizeSpec size;
  size.nominal = designation.size.nominal;
  size.lower_deviation = found.pitch_diameter.lower_deviation;
  size.upper_deviation = found.pitch_diameter.upper_deviation;
  size.iso_code = designation.text;
  size.pitch = designation.size.pitch;
  size.crest_lower_deviation = crest.lower_deviation;
  size.crest_upper_deviation = crest.upper_deviation;
  return size;
}

SizeSpec ParseExplicitSize(const ConfigNode& node) {
  node.ExpectOnlyKeys({"nominal", "lower", "upper"});
  SizeSpec size;
  size.nominal = node.Child("nominal").AsQuantityIn(Dimension::kLength, 0.0, limits::kMaxNominal,
                                                    /*min_inclusive=*/false);
  const ConfigNode lower = node.Child("lower");
  const ConfigNode upper = node.Child("upper");
  size.lower_deviation = lower.AsQuantity(Dimension::kLength);
  size.upper_deviation = upper.AsQuantity(Dimension::kLength);
  if (!(size.nominal + size.lower_deviation > 0.0)) {
    lower.Fail("a lower deviation above -" + FormatQuantity(size.nominal, Dimension::kLength) +
                   " (the smallest size must be positive)",
               lower.Describe());
  }
  // A tolerance zone of zero width cannot be manufactured, and an inverted pair is a typing error.
  if (!(size.upper_deviation > size.lower_deviation)) {
    upper.Fail("an upper deviation greater than the lower deviation (" +
                   FormatQuantity(size.lower_deviation, Dimension::kLength) + ")",
               upper.Describe() + (size.upper_deviation < size.lower_deviation
                                       ? " (the limits are inverted)"
                                       : " (a tolerance zone of zero width)"));
  }
  return size;
}

FormSpec ParseForm(const ConfigNode& node, const SurfaceType& surface,
                   const std::string& surface_id, double nominal) {
  const std::vector<FormCharacteristic> supported = surface.form_characteristics();
  const std::vector<SurfaceType::DeclaredCharacteristic> declared =
      surface.declared_characteristics();
  std::string names;
  for (FormCharacteristic c : supported) names += (names.empty() ? "" : ", ") + ToString(c);
  for (const auto& d : declared) names += (names.empty() ? "" : ", ") + d.name;
  const std::string expected = "a form characteristic that " + surface_id + " models (" +
                               (names.empty() ? "none" : names) + ")";
  FormSpec form;
  for (const std::string& key : node.Keys()) {  // a map of plain keys, none repeated
    const FormCharacteristic* match = nullptr;
    for (const FormCharacteristic& c : supported) {
      if (ToString(c) == key) match = &c;
    }
    const SurfaceType::DeclaredCharacteristic* own = nullptr;
    for (const auto& d : declared) {
      if (d.name == key) own = &d;
    }
    if (own != nullptr) {
      form.declared[key] = node.Child(key).AsQuantityIn(own->dimension, 0.0, own->max);
      continue;
    }
    if (match == nullptr) {
      bool known = false;
      for (int i = 0; i <= static_cast<int>(FormCharacteristic::kSphericity); ++i) {
        known = known || ToString(static_cast<FormCharacteristic>(i)) == key;
      }
      // Reported at the key, like every other unknown key.
      throw ScenarioError(node.KeyLocation(key), node.path() + "." + key, expected,
                          known ? "'" + key + "', which this surface type does not model"
                                : "unknown key '" + key + "'");
    }
    // A form deviation as large as the part itself describes no real part.
    form.tolerance[*match] = node.Child(key).AsQuantityIn(Dimension::kLength, 0.0, nominal);
  }
  return form;
}

TextureSpec ParseTexture(const ConfigNode& node) {
  node.ExpectOnlyKeys({"waviness", "Ra", "Rz"});
  TextureSpec texture;
  auto optional = [&](const char* key) {
    std::optional<ConfigNode> child = node.Find(key);
    return child ? child->AsQuantityIn(Dimension::kLength, 0.0, limits::kMaxTexture) : 0.0;
  };
  texture.waviness = optional("waviness");
  texture.ra = optional("Ra");
  texture.rz = optional("Rz");
  // Rz is a peak-to-valley height and Ra a mean absolute deviation of the same profile, so Rz >= Ra
  // always holds for a real surface.
  if (texture.rz < texture.ra) {
    const std::string expected = "Rz >= Ra (" + FormatQuantity(texture.ra, Dimension::kLength) +
                                 "): a peak-to-valley height is never below the mean deviation";
    if (std::optional<ConfigNode> rz = node.Find("Rz")) {
      rz->Fail(expected, rz->Describe() + " (Ra > Rz is physically impossible)");
    }
    throw ScenarioError(
        node.location(), node.path() + ".Rz", expected,
        "no Rz (taken as 0) with Ra = " + FormatQuantity(texture.ra, Dimension::kLength));
  }
  return texture;
}

Material ParseMaterial(const ConfigNode& node) {
  node.ExpectOnlyKeys({"name", "youngs_modulus", "poisson", "yield_strength"});
  Material material;
  material.name = node.StringOr("name", "");
  material.youngs_modulus = node.QuantityIn("youngs_modulus", Dimension::kPressure,
                                            limits::kMinYoungsModulus, limits::kMaxYoungsModulus);
  const ConfigNode poisson = node.Child("poisson");
  material.poisson = poisson.AsQuantity(Dimension::kDimensionless);
  if (!PoissonInRange(material.poisson)) {
    poisson.Fail("a Poisson's ratio in [0, 0.5) (the range of every resistance law)",
                 poisson.Describe());
  }
  if (std::optional<ConfigNode> yield = node.Find("yield_strength")) {
    // Soft solders (~10 MPa) to maraging steels and tungsten (~2.5 GPa), below E by far.
    material.yield_strength = yield->AsQuantityIn(Dimension::kPressure, 1e6, 5e9);
  }
  return material;
}

// `process: paper` or `process: {model: statistical, cp: 1.33, cpk: 1.33, form_cpk: 1.33,
// lean: maximum_material}` (every key but model optional).
ProcessSpec ParseProcess(const ConfigNode& node) {
  ProcessSpec process;
  const auto model_of = [](const ConfigNode& n) {
    return n.AsOneOf({"paper", "statistical"}) == "paper" ? ProcessKind::kPaper
                                                          : ProcessKind::kStatistical;
  };
  if (node.is_scalar()) {
    process.kind = model_of(node);
    return process;
  }
  node.ExpectOnlyKeys({"model", "cp", "cpk", "form_cpk", "lean"});
  process.kind = model_of(node.Child("model"));
  if (process.kind == ProcessKind::kPaper && node.Keys().size() > 1) {
    node.Fail("only `model: paper` (the paper's uniform draws take no capability)",
              "capability keys with model: paper");
  }
  auto index = [&](const char* key, double fallback) {
    std::optional<ConfigNode> child = node.Find(key);
    return child ? child->AsQuantityIn(Dimension::kDimensionless, 0.1, 10.0) : fallback;
  };
  process.cp = index("cp", process.cp);
  process.cpk = index("cpk", std::min(process.cp, process.cpk));
  process.form_cpk = index("form_cpk", process.form_cpk);
  if (process.cpk > process.cp) {
    const ConfigNode at = node.Find("cpk") ? *node.Find("cpk") : node;
    char cp[32];
    std::snprintf(cp, sizeof cp, "%g", process.cp);
    at.Fail(std::string("cpk <= cp (") + cp + "): Cpk never exceeds Cp", at.Describe());
  }
  if (std::optional<ConfigNode> lean = node.Find("lean")) {
    process.lean = lean->AsOneOf({"maximum_material", "least_material"}) == "maximum_material"
                       ? ProcessLean::kMaximumMaterial
                       : ProcessLean::kLeastMaterial;
  }
  return process;
}

// `measured: {roundness: FILE}` (or straightness, or points): FILE relative to the scenario's
// folder.
std::shared_ptr<const MeasuredSurface> ParseMeasured(const ConfigNode& node,
                                                     double nominal_radius) {
  node.ExpectOnlyKeys({"roundness", "straightness", "points"});
  const std::vector<std::string> keys = node.Keys();
  if (keys.size() != 1) {
    node.Fail("one measurement: roundness, straightness or points (a file each)",
              std::to_string(keys.size()) + " keys");
  }
  const MeasurementKind kind = keys[0] == "roundness"      ? MeasurementKind::kRoundness
                               : keys[0] == "straightness" ? MeasurementKind::kStraightness
                                                           : MeasurementKind::kPoints;
  const ConfigNode file = node.Child(keys[0]);
  std::filesystem::path path = file.AsString();
  if (path.is_relative()) path = std::filesystem::path(node.file()).parent_path() / path;
  return std::make_shared<const MeasuredSurface>(ReadMeasurement(path, kind, nominal_radius, file));
}

}  // namespace

SizeSpec ParseSize(const ConfigNode& node, Role role) {
  if (node.is_scalar()) {
    return iso965::LooksLikeThread(node.AsString()) ? ParseThreadSize(node, role)
                                                    : ParseIsoSize(node, role);
  }
  if (node.is_map()) return ParseExplicitSize(node);
  node.Fail(kSizeForms, node.Describe());
}

PartSpec ParsePart(const std::string& name, const ConfigNode& node, const SurfaceType& surface,
                   const std::string& surface_id) {
  node.ExpectOnlyKeys(
      {"role", "size", "geometry", "form", "texture", "material", "process", "measured"});
  PartSpec part;
  part.name = name;
  part.role =
      node.Child("role").AsOneOf({"inner", "outer"}) == "inner" ? Role::kInner : Role::kOuter;
  part.size = ParseSize(node.Child("size"), part.role);
  if (std::optional<ConfigNode> form = node.Find("form")) {
    part.form = ParseForm(*form, surface, surface_id, part.size.nominal);
  }
  if (std::optional<ConfigNode> texture = node.Find("texture")) {
    part.texture = ParseTexture(*texture);
  }
  part.material = ParseMaterial(node.Child("material"));
  if (std::optional<ConfigNode> process = node.Find("process")) {
    part.process = ParseProcess(*process);
  }
  if (std::optional<ConfigNode> measured = node.Find("measured")) {
    if (node.Has("process")) {
      node.Child("process").Fail("no process for a measured part (it is not drawn)",
                                 "both `process` and `measured`");
    }
    part.measured = ParseMeasured(*measured, part.size.nominal / 2.0);
  }
  return part;
}

}  // namespace fitfeel::scenario
