#include "framework/plot/scene_shapes.h"

#include <utility>

#include "framework/core/error.h"
#include "framework/model/surface_type.h"
#include "framework/runtime/prepare.h"

namespace fitfeel::plot {

SceneShapes GenerateSceneShapes(Scene scene, std::optional<std::uint64_t> seed) {
  if (!scene.surface) {
    throw UserError("scene '" + scene.name + "' has no surface type '" + scene.surface_id + "'");
  }
  SceneShapes shapes;
  shapes.seed = seed.value_or(scene.run.seed);
  Rng rng(shapes.seed);
  SkinModelShapes drawn = GenerateSkinModelShapes(scene, rng);
  shapes.inner = std::move(drawn.inner);
  shapes.outer = std::move(drawn.outer);
  shapes.scene = std::move(scene);
  return shapes;
}

void CheckSameGrids(const SceneShapes& shapes, std::optional<std::pair<int, int>> run_inner,
                    std::optional<std::pair<int, int>> run_outer) {
  const auto check = [&](const char* which, const SurfaceGrid& grid,
                         const std::optional<std::pair<int, int>>& recorded) {
    if (!recorded || (recorded->first == grid.rows && recorded->second == grid.columns)) return;
    throw UserError("the scenario now gives the " + std::string(which) + " part a grid of " +
                    std::to_string(grid.rows) + " x " + std::to_string(grid.columns) +
                    " cells, the run had " + std::to_string(recorded->first) + " x " +
                    std::to_string(recorded->second) +
                    ": the scenario file changed since the run; run it again");
  };
  check("inner", shapes.inner.grid, run_inner);
  check("outer", shapes.outer.grid, run_outer);
}

PreparedContact PrepareContact(const SceneShapes& shapes, const std::string& law) {
  const Scene& scene = shapes.scene;
  PreparedContact prepared;
  prepared.analyzer = scene.surface->MakeContactAnalyzer();
  if (!prepared.analyzer) {
    throw UnsupportedError("surface type '" + scene.surface_id + "' provides no contact analyzer");
  }
  prepared.analyzer->Prepare(scene.inner, shapes.inner, scene.outer, shapes.outer, scene.model);
  prepared.law = scene.surface->MakeLaw(law.empty() ? scene.model.law : law);
  prepared.law->Prepare(scene.inner, scene.outer, scene.model);
  return prepared;
}

}  // namespace fitfeel::plot
