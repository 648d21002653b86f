#include "framework/scenario/sequence.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "framework/scenario/scene_sections.h"
#include "framework/scenario/scene_summary.h"
#include "framework/scenario/yaml_file.h"

namespace fitfeel {

bool IsSequenceFile(const std::filesystem::path& file) {
  try {
    const ConfigNode root = scenario::LoadYamlFile(file);
    return root.is_map() && root.Has("steps");
  } catch (const std::exception&) {
    return false;
  }
}

Sequence LoadSequence(const std::filesystem::path& file, const PluginRegistry& registry,
                      const LoadOptions& options) {
  const ConfigNode root = scenario::LoadYamlFile(file);
  if (!root.is_map()) root.Fail("a map of scenario keys (scenario, steps, run)", root.Describe());
  root.ExpectOnlyKeys({"scenario", "description", "steps", "run"});
  for (const char* key : {"scenario", "steps", "run"}) root.Child(key);
  Sequence sequence;
  sequence.file = file;
  const ConfigNode name = root.Child("scenario");
  sequence.name = name.AsString();
  if (!scenario::IsPlainName(sequence.name)) {
    name.Fail("a scenario name of letters, digits, '_', '-' or '.' (it names outputs)",
              name.Describe());
  }
  sequence.description = root.StringOr("description", "");
  sequence.run = scenario::ParseRun(root.Child("run"), /*sequence=*/true);
  const ConfigNode steps = root.Child("steps");
  if (!steps.is_sequence()) steps.Fail("a list of steps", steps.Describe());
  const std::vector<ConfigNode> items = steps.Items();
  if (items.empty()) steps.Fail("at least one step", "an empty list");
  std::vector<std::string> names;
  for (const ConfigNode& item : items) {
    if (!item.is_map()) item.Fail("a map describing the step (step, moving, ...)", item.Describe());
    SequenceStep step;
    step.scene = scenario::LoadSceneFrom(item, file, registry, options, &sequence.run);
    const ConfigNode step_name = item.Child("step");
    if (std::find(names.begin(), names.end(), step.scene.name) != names.end()) {
      step_name.Fail("a step name no earlier step has (it names the step's outputs)",
                     step_name.Describe());
    }
    if (std::optional<ConfigNode> seated = item.Find("seated")) {
      if (!seated->is_map()) {
        seated->Fail("a map from a feature of the step to the earlier step that seated its part",
                     seated->Describe());
      }
      for (const std::string& feature : seated->Keys()) {
        const ConfigNode entry = seated->Child(feature);
        // `feature: step`, or `feature: {step, carry: x | z | both}`.
        bool carry_x = true, carry_z = true;
        if (entry.is_map()) {
          entry.ExpectOnlyKeys({"step", "carry"});
          if (std::optional<ConfigNode> carry = entry.Find("carry")) {
            const std::string axes = carry->AsOneOf({"x", "z", "both"});
            carry_x = axes != "z";
            carry_z = axes != "x";
          }
        }
        const ConfigNode by = entry.is_map() ? entry.Child("step") : entry;
        const auto& features = step.scene.features;
        const auto f = std::find_if(features.begin(), features.end(),
                                    [&](const MatingFeature& m) { return m.name == feature; });
        if (f == features.end()) {
          std::vector<std::string> known;
          for (const MatingFeature& m : features) known.push_back(m.name);
          seated->Fail("a feature of the step (" + scenario::JoinList(known) + ")",
                       "'" + feature + "'");
        }
        if (f == features.begin()) {
          by.Fail("a feature other than the datum (the datum's axis is the joint's own)",
                  "the datum '" + feature + "'");
        }
        if (names.empty()) by.Fail("the name of an earlier step", "a seat on the first step");
        const std::string earlier =
            by.AsOneOf(std::vector<std::string_view>(names.begin(), names.end()));
        const auto k = std::find(names.begin(), names.end(), earlier) - names.begin();
        step.seated.push_back(
            {static_cast<int>(f - features.begin()), static_cast<int>(k), carry_x, carry_z});
      }
    }
    names.push_back(step.scene.name);
    sequence.steps.push_back(std::move(step));
  }
  return sequence;
}

std::string DescribeSequence(const Sequence& sequence) {
  std::string out = "scenario     " + sequence.name + " (" + sequence.file.string() + "), " +
                    std::to_string(sequence.steps.size()) + " steps in order\n";
  if (!sequence.description.empty()) out += "description  " + sequence.description + "\n";
  for (std::size_t i = 0; i < sequence.steps.size(); ++i) {
    const SequenceStep& step = sequence.steps[i];
    out += "\nstep " + std::to_string(i + 1) + "       " + step.scene.name + "\n";
    for (const SequenceStep::Seat& seat : step.seated) {
      out += "seated       feature " + step.scene.features[seat.feature].name +
             " sits where step " + sequence.steps[seat.step].scene.name + " left its part (" +
             (seat.x && seat.z ? "x and z" : seat.x ? "x" : "z") + ")\n";
    }
    out += DescribeScene(step.scene);
  }
  return out;
}

}  // namespace fitfeel
