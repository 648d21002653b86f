#include "framework/view/scene_edits.h"

#include <array>
#include <set>
#include <stdexcept>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "framework/iso286/iso286.h"

namespace fitfeel::view {
namespace {

YAML::Node Parse(const std::string& yaml, const std::string& name) {
  try {
    return YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw ScenarioError({name, e.mark.line + 1, e.mark.column + 1}, "", "YAML", e.msg);
  }
}

// "20 mm js6" -> ("20 mm", "js6") when the last word is a class ISO 286 defines at the nominal
// size the words before it give; nothing otherwise (deviations, a thread, a plain size).
bool SplitIsoSize(const std::string& text, std::string* nominal, std::string* iso_class,
                  double* nominal_m) {
  const std::size_t space = text.find_last_of(' ');
  if (space == std::string::npos) return false;
  const std::string head = text.substr(0, text.find_last_not_of(' ', space) + 1);
  const std::string code = text.substr(space + 1);
  try {
    *nominal_m = ParseQuantity(head, Dimension::kLength);
    iso286::Lookup(*nominal_m, code);
  } catch (const std::exception&) {
    return false;
  }
  *nominal = head;
  *iso_class = code;
  return true;
}

std::vector<std::string> ClassesAt(double nominal_m, bool hole) {
  static constexpr std::array<std::string_view, 28> kLetters = {
      "a", "b", "c", "cd", "d", "e", "ef", "f", "fg", "g", "h", "js", "j",  "k",
      "m", "n", "p", "r",  "s", "t", "u",  "v", "x",  "y", "z", "za", "zb", "zc"};
  std::vector<std::string> out;
  for (std::string_view letter : kLetters) {
    for (int grade = 4; grade <= 11; ++grade) {
      std::string code(letter);
      if (hole) {
        for (char& c : code) c = static_cast<char>(c - 'a' + 'A');
      }
      code += std::to_string(grade);
      try {
        iso286::Lookup(nominal_m, code);
        out.push_back(code);
      } catch (const std::exception&) {
        // Not defined at this size and grade: not offered.
      }
    }
  }
  return out;
}

void AddScalars(const YAML::Node& map, const std::string& prefix, const std::string& label,
                std::vector<EditableField>* fields) {
  if (!map || !map.IsMap()) return;
  for (const auto& entry : map) {
    if (!entry.second.IsScalar()) continue;
    const std::string key = entry.first.as<std::string>();
    EditableField f;
    f.path = prefix + "." + key;
    f.label = label + " " + key;
    f.value = entry.second.Scalar();
    fields->push_back(std::move(f));
  }
}

std::vector<EditableField> FieldsOf(const YAML::Node& root) {
  std::vector<EditableField> fields;
  if (!root.IsMap()) return fields;
  const YAML::Node parts = root["parts"];
  if (parts && parts.IsMap() && parts.size() == 2) {
    for (const auto& part : parts) {
      const std::string part_name = part.first.as<std::string>();
      const YAML::Node spec = part.second;
      if (!spec.IsMap()) continue;
      const std::string prefix = "parts." + part_name;
      if (spec["size"] && spec["size"].IsScalar()) {
        EditableField f;
        f.path = prefix + ".size";
        f.label = part_name + " size";
        f.value = spec["size"].Scalar();
        double nominal_m = 0.0;
        if (SplitIsoSize(f.value, &f.nominal, &f.iso_class, &nominal_m)) {
          const bool hole = !f.iso_class.empty() && f.iso_class[0] >= 'A' && f.iso_class[0] <= 'Z';
          f.classes = ClassesAt(nominal_m, hole);
        }
        fields.push_back(std::move(f));
      }
      AddScalars(spec["form"], prefix + ".form", part_name + " form", &fields);
      AddScalars(spec["texture"], prefix + ".texture", part_name + " texture", &fields);
    }
  }
  if (const YAML::Node model = root["model"];
      model && model.IsMap() && model["friction"] && model["friction"].IsScalar()) {
    fields.push_back({"model.friction", "friction", model["friction"].Scalar(), "", "", {}});
  }
  const YAML::Node run = root["run"];
  const std::string seed =
      run && run.IsMap() && run["seed"] && run["seed"].IsScalar() ? run["seed"].Scalar() : "1";
  fields.push_back({"run.seed", "seed", seed, "", "", {}});
  return fields;
}

}  // namespace

std::vector<EditableField> EditableFields(const std::string& yaml, const std::string& name) {
  return FieldsOf(Parse(yaml, name));
}

std::vector<std::string> FitsAt(double nominal_m) {
  static constexpr std::array<std::string_view, 15> kFits = {
      "H11/c11", "H9/d9", "H8/e8", "H8/f7", "H7/f7", "H7/g6", "H7/h6", "H7/js6",
      "H7/k6",   "H7/m6", "H7/n6", "H7/p6", "H7/r6", "H7/s6", "H7/u6"};
  std::vector<std::string> out;
  for (std::string_view fit : kFits) {
    const std::size_t slash = fit.find('/');
    try {
      iso286::Lookup(nominal_m, fit.substr(0, slash));
      iso286::Lookup(nominal_m, fit.substr(slash + 1));
      out.emplace_back(fit);
    } catch (const std::exception&) {
      // Not defined at this size: not offered.
    }
  }
  return out;
}

std::string ApplyEdits(const std::string& yaml, const std::string& name,
                       const std::map<std::string, std::string>& edits) {
  YAML::Node root = Parse(yaml, name);
  std::set<std::string> editable;
  for (const EditableField& f : FieldsOf(root)) editable.insert(f.path);
  for (const auto& [path, value] : edits) {
    if (editable.count(path) == 0) {
      std::string list;
      for (const std::string& p : editable) list += (list.empty() ? "" : ", ") + p;
      throw ScenarioError({name, 0, 0}, path, "one of the editable keys (" + list + ")",
                          "a key the page may not change");
    }
    if (value.find_first_of("\r\n") != std::string::npos || value.empty()) {
      throw ScenarioError({name, 0, 0}, path, "one line of text",
                          value.empty() ? "nothing" : value);
    }
    // Walk the path, creating `run` and its `seed` where the file gives neither.
    YAML::Node node = root;
    std::size_t begin = 0;
    while (true) {
      const std::size_t dot = path.find('.', begin);
      const std::string key = path.substr(begin, dot - begin);
      if (dot == std::string::npos) {
        node[key] = value;
        break;
      }
      YAML::Node next = node[key];
      node.reset(next);
      begin = dot + 1;
    }
  }
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

nlohmann::json FieldsJson(const std::vector<EditableField>& fields) {
  nlohmann::json out = nlohmann::json::array();
  for (const EditableField& f : fields) {
    nlohmann::json j = {{"path", f.path}, {"label", f.label}, {"value", f.value}};
    if (!f.iso_class.empty()) {
      j["nominal"] = f.nominal;
      j["class"] = f.iso_class;
      j["classes"] = f.classes;
    }
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace fitfeel::view
