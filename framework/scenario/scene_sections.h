#pragma once

// The scenario loader's section parsers, shared by the one-feature loader (scene.cc) and the
// several-feature one (features.cc). Internal to the scenario library.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/config_node.h"
#include "framework/core/error.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"

namespace fitfeel::scenario {

// Runs a plugin's check on `node`: a plugin that refuses with a plain UserError (no location of its
// own) is refused at `node`, so that no refusal reaches the user without file, line and key.
template <typename Check>
auto Located(const ConfigNode& node, const std::string& expected, Check&& check) {
  try {
    return check();
  } catch (const ScenarioError&) {
    throw;
  } catch (const UserError& e) {
    node.Fail(expected, e.what());
  }
}

// "a, b, c"; "none" for no items.
std::string JoinList(const std::vector<std::string>& items);
// Names end up in output paths and summaries, so they stay portable.
bool IsPlainName(const std::string& name);

// The surface type `node` names, refused at `node` when not loaded, not rendering (unless the
// options allow it) or without a law.
std::shared_ptr<SurfaceType> ResolveSurface(const ConfigNode& node, const PluginRegistry& registry,
                                            const LoadOptions& options, std::string* id);

struct Parts {
  PartSpec inner;
  PartSpec outer;
  Role moving = Role::kInner;
};
// The `parts` map of two parts (`node`), one inner and one outer, and which of them `moving`
// names.
Parts ParseParts(const ConfigNode& node, const ConfigNode& moving, const SurfaceType& surface,
                 const std::string& surface_id);

ModelSettings ParseModel(const ConfigNode& node, const SurfaceType& surface,
                         const std::string& surface_id, const Parts& parts);

// The grid each part gets and what preparing the pair costs; refuses, at the key that causes it,
// a resolution the surface type cannot discretize, a depth table over the analyzers' cap and,
// unless `allow_large`, a cost over the large-scene thresholds (at `model_node`'s keys) or
// outputs over the large-output one (at `duration`).
SceneCost CheckPrepare(const ConfigNode& model_node, const ConfigNode& duration,
                       const SurfaceType& surface, const PartSpec& inner, const PartSpec& outer,
                       const ModelSettings& model, const RunSettings& run,
                       const LoadOptions& options);

// The `features` section of a several-feature scene; fills scene->features and the datum
// feature's fields (surface, inner, outer, moving, model) and adds their preparation to
// scene->cost. `root` is the scenario's map.
void ParseFeatures(const ConfigNode& root, const ConfigNode& duration,
                   const PluginRegistry& registry, const LoadOptions& options, Scene* scene);

// The `run` section: with `sequence`, a sequence's (rate, seed, clock and outputs; each step gives
// its own duration).
RunSettings ParseRun(const ConfigNode& node, bool sequence);

// One scene from its map: a scenario (`step_run` null) or a step of a sequence, which has `step`
// for `scenario`, `duration` for `run` (the rest of the run is the sequence's, `*step_run`) and
// may say which of its features sit on a part an earlier step seated (`seated`, read by the
// sequence's loader).
Scene LoadSceneFrom(const ConfigNode& root, const std::filesystem::path& file,
                    const PluginRegistry& registry, const LoadOptions& options,
                    const RunSettings* step_run = nullptr);

}  // namespace fitfeel::scenario
