#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/model/skin_model_shape.h"
#include "framework/scenario/scene.h"

namespace fitfeel::plot {

// A loaded scene with the skin model shapes of both parts.
struct SceneShapes {
  Scene scene;
  std::uint64_t seed = 0;
  SkinModelShape inner;
  SkinModelShape outer;
};

// Draws both parts' skin model shapes exactly as a run's prepare does (framework/runtime): one
// generator seeded from `seed` (default: the scene's run.seed), both grids discretized first, then
// the inner part's shape drawn, then the outer part's. The same scene and seed therefore give the
// shapes the run used, bit for bit. Throws UnsupportedError when the surface type offers no
// discretizer or generator.
FITFEEL_API SceneShapes GenerateSceneShapes(Scene scene,
                                            std::optional<std::uint64_t> seed = std::nullopt);

// Throws UserError when the shapes' grids differ from those a run recorded (rows x columns of the
// inner and outer part): the scenario file changed since the run, so its pictures would not be
// the run's. Unrecorded grids are not checked.
FITFEEL_API void CheckSameGrids(const SceneShapes& shapes,
                                std::optional<std::pair<int, int>> run_inner,
                                std::optional<std::pair<int, int>> run_outer);

struct PreparedContact {
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
};

// Prepares the surface's contact analyzer on the shapes and the law named `law` (the scene's
// when empty), as a run's prepare does.
FITFEEL_API PreparedContact PrepareContact(const SceneShapes& shapes, const std::string& law = "");

}  // namespace fitfeel::plot
