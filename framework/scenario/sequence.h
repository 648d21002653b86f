#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

class PluginRegistry;

// One step of an assembly sequence (docs/assemblies.md): a scene of its own, run after the steps
// before it, whose features may sit on a part an earlier step seated.
struct SequenceStep {
  Scene scene;  // scene.name is the step's name; its run is the sequence's with its duration
  // Features of this step whose fixed side is the part an earlier step moved and seated: the
  // feature's index in scene.features and the step's index. That feature's fixed side sits where
  // the step left its part, across its axis (FeaturePlacement::seat).
  struct Seat {
    int feature = 0;
    int step = 0;
    // Which of the step's offsets across its axis carry over: x, z or both (the steps' frames
    // agree across their axes only where the user says so: a key pressed into its keyway moves
    // across the shaft, and only its x, across its flanks, is the hub step's x).
    bool x = true;
    bool z = true;
  };
  std::vector<Seat> seated;
};

// An ordered list of steps (the scenario's `steps`), every step checked as a scene is.
struct Sequence {
  std::filesystem::path file;
  std::string name;
  std::string description;
  RunSettings run;  // rate, seed, clock and outputs shared by the steps (no duration)
  std::vector<SequenceStep> steps;
};

// Whether `file` holds a sequence (a top-level `steps`); false for anything else, including a
// file that cannot be read (the loader then says why).
FITFEEL_API bool IsSequenceFile(const std::filesystem::path& file);

// Parses and checks a sequence: every step as LoadScene checks a scene, the step names plain and
// distinct, each `seated` naming one of the step's features and an earlier step. Throws
// ScenarioError, located, for any problem.
FITFEEL_API Sequence LoadSequence(const std::filesystem::path& file, const PluginRegistry& registry,
                                  const LoadOptions& options = {});

// What `fitfeel validate` prints of a sequence: its steps, each as DescribeScene describes a scene.
FITFEEL_API std::string DescribeSequence(const Sequence& sequence);

}  // namespace fitfeel
