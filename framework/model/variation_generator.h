#pragma once

#include <random>

#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel {

// The scene owns the only random generator; every draw of a run comes from it, in a fixed order,
// so a scenario and seed give the same skin model shapes bit for bit.
using Rng = std::mt19937_64;

// How the surface texture enters the model (paper eq. 6 and its discussion).
enum class TextureMode {
  kExpected,  // not sampled into V; the analyzer uses the expected interference of its distribution
  kSampled,   // a truncated-Gaussian draw per cell added to V
};

// Prepare-time: draws the variation V of every cell of a part so that it meets the part's GPS
// spec (paper section 2.2, steps 2 and 3).
class FITFEEL_API VariationGenerator {
 public:
  virtual ~VariationGenerator();
  SkinModelShape Generate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                          Rng& rng) const;
  // Applies the surface type's keys of the scenario's `model.options` (ModelSettings::extra),
  // once, before Generate; throws ScenarioError at an unknown or malformed key. Whoever prepares
  // a scene calls it when `extra` is present. The default accepts no key.
  void Configure(const ConfigNode& options);

 protected:
  virtual void DoConfigure(const ConfigNode& options);
  virtual SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                    TextureMode texture, Rng& rng) const = 0;
  // The process models (PartSpec::process) the generator draws from; the default, the paper's.
  virtual bool DoSupports(ProcessKind kind) const { return kind == ProcessKind::kPaper; }
};

}  // namespace fitfeel
