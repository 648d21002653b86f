#pragma once

#include <random>

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"
#include "framework/model/surface_options.h"

namespace fitfeel {

// The scene owns the only random generator; every draw of a run comes from it, in a fixed order,
// so a scenario and seed give the same skin model shapes bit for bit.
using Rng = std::mt19937_64;

// Uniform in [0, 1) from the top 53 bits of one draw: the same number on every platform, where
// the standard library's distributions are implementation-defined.
inline double UniformDraw(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// How the surface texture enters the model (paper eq. 6 and its discussion).
enum class TextureMode {
  kExpected,  // not sampled into V; the analyzer uses the expected interference of its distribution
  kSampled,   // a truncated-Gaussian draw per cell added to V
  // Waviness drawn into V as geometry; roughness removed from the interference by DIN 7190-1
  // smoothing (0.8 (Rz_i + Rz_a) on the diameter) in the contact analysis.
  kDin7190,
};

// The scenario's name of a texture mode (model.texture).
inline const char* TextureModeName(TextureMode mode) {
  switch (mode) {
    case TextureMode::kExpected:
      return "expected";
    case TextureMode::kSampled:
      return "sampled";
    case TextureMode::kDin7190:
      return "din7190";
  }
  return "?";
}

// Prepare-time: draws the variation V of every cell of a part so that it meets the part's GPS
// spec (paper section 2.2, steps 2 and 3).
class FITFEEL_API VariationGenerator {
 public:
  virtual ~VariationGenerator();
  SkinModelShape Generate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                          Rng& rng) const;
  // Takes the scene's parsed `model.options` (ModelSettings::options, which the surface type's
  // ParseOptions made), once, before Generate; whoever prepares a scene calls it when the scene
  // has options. Throws UserError for another surface type's options.
  void Configure(const SurfaceOptions& options);

 protected:
  // Default: the generator has no options of its own.
  virtual void DoConfigure(const SurfaceOptions& options);
  virtual SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                    TextureMode texture, Rng& rng) const = 0;
  // The process models (PartSpec::process) the generator draws from; the default, the paper's.
  virtual bool DoSupports(ProcessKind kind) const { return kind == ProcessKind::kPaper; }
};

}  // namespace fitfeel
