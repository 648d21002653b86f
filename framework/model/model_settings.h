#pragma once

#include <optional>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/discretizer.h"
#include "framework/model/variation_generator.h"

namespace fitfeel {

// The largest depth tables a contact analyzer builds (their rows are depth steps along the mating
// axis, each with up to columns + 4 polygon vertices): a step far finer than the grid's rows buys
// nothing, since cells are piecewise constant, and 1e8 vertices are 1.6 GB. The scenario loader
// refuses a depth_step beyond them, the analyzers never build one.
inline constexpr double kMaxDepthSteps = 2e6;
inline constexpr double kMaxDepthTableVertices = 1e8;

// The scenario's `model` section, in SI.
struct ModelSettings {
  std::string law;                     // law name offered by the surface type ("gps", "ve1", ...)
  double friction = 0.0;               // Coulomb coefficient mu
  double contact_stiffness = 0.0;      // k_p, N/m (eq. 9)
  Resolution resolution;               // m x n, or auto
  TextureMode texture = TextureMode::kExpected;
  double depth_step = 0.0;             // tabulation step along the mating axis, m (0 = auto)
  std::optional<ConfigNode> extra;     // surface-specific keys under model.options, if any
};

}  // namespace fitfeel
