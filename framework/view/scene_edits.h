#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/export.h"

namespace fitfeel::view {

// What a live view's page may change in a one-feature scenario: each part's size (its ISO 286
// class, with the classes the standard defines at its nominal size), its form and texture values,
// the friction and the seed. Key paths are the scenario's own ("parts.shaft.size",
// "parts.bushing.form.roundness", "model.friction", "run.seed"), so that the loader's messages
// about an edited value name the key the page shows.
struct EditableField {
  std::string path;   // the scenario's key path
  std::string label;  // what the page shows ("shaft size")
  std::string value;  // the scenario's text for it ("20 mm js6", "10 um", "0.15")
  // A size given as an ISO 286 class: the nominal size's text ("20 mm"), the class ("js6") and
  // every class of its kind (holes or shafts) that ISO 286-1 defines there, grades 4 to 11.
  std::string nominal;
  std::string iso_class;
  std::vector<std::string> classes;
};

// The fields of scenario text `yaml` that the page may edit, in the file's order. A scenario
// without a `parts` map of two parts (several features, a sequence) gives friction and seed only.
// Throws ScenarioError (name:line:column) for text that is not YAML.
FITFEEL_API std::vector<EditableField> EditableFields(const std::string& yaml,
                                                      const std::string& name);

// The hole-basis fits of the handbooks' preferred lists (ISO 286-1's examples and ANSI B4.2's
// preferred metric fits, from H11/c11 to H7/u6) that ISO 286 defines at `nominal_m`, as "H7/g6":
// the page's list of fits, which sets both parts' classes at once.
FITFEEL_API std::vector<std::string> FitsAt(double nominal_m);

// The scenario text with each (key path, value) of `edits` set: the value replaces the scalar at
// that path, which must be one of EditableFields' paths (or run.seed, added when the file has
// none). The text is emitted again from its YAML tree: its values and order are kept, its
// comments are not. Throws ScenarioError naming the key path for a path that is not editable and
// for a value with a line break; the values themselves are checked by loading the result
// (LoadSceneFromYaml), which locates what it refuses.
FITFEEL_API std::string ApplyEdits(const std::string& yaml, const std::string& name,
                                   const std::map<std::string, std::string>& edits);

// The fields as the panel message carries them.
FITFEEL_API nlohmann::json FieldsJson(const std::vector<EditableField>& fields);

}  // namespace fitfeel::view
