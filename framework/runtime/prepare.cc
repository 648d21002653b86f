#include "framework/runtime/prepare.h"

#include <chrono>
#include <utility>

#include "framework/core/error.h"
#include "framework/model/measured_surface.h"

namespace fitfeel {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

PreparedScene::PreparedScene() = default;
PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

SkinModelShapes GenerateSkinModelShapes(const Scene& scene, Rng& rng) {
  if (!scene.surface) {
    throw UserError("scene '" + scene.name + "' has no surface type '" + scene.surface_id + "'");
  }
  // One discretizer and generator for both parts: the surface type decides the grid of each part
  // from its own geometry.
  SkinModelShapes shapes;
  auto t = Clock::now();
  const auto discretizer = scene.surface->MakeDiscretizer();
  const auto generator = scene.surface->MakeVariationGenerator();
  if (!discretizer || !generator) {
    throw UnsupportedError("surface type '" + scene.surface_id +
                           "' provides no discretizer or variation generator");
  }
  if (scene.model.options) generator->Configure(*scene.model.options);
  const SurfaceGrid inner_grid = discretizer->Discretize(scene.inner, scene.model.resolution);
  const SurfaceGrid outer_grid = discretizer->Discretize(scene.outer, scene.model.resolution);
  shapes.discretize_seconds = SecondsSince(t);
  t = Clock::now();
  // A measured part takes no draw: the other part's draws are those it gets with the same seed
  // when it comes first, not otherwise (docs/measured-parts.md).
  auto shape = [&](const PartSpec& part, const SurfaceGrid& grid) {
    return part.measured
               ? MeasuredSkinModelShape(*part.measured, grid, part.size.nominal / 2.0)
               : generator->Generate(part, grid, scene.model.texture, rng);
  };
  shapes.inner = shape(scene.inner, inner_grid);
  shapes.outer = shape(scene.outer, outer_grid);
  shapes.generate_seconds = SecondsSince(t);
  return shapes;
}

PreparedScene Prepare(const Scene& scene) {
  if (!scene.surface) {
    throw UserError("scene '" + scene.name + "' has no surface type '" + scene.surface_id + "'");
  }
  if (!scene.surface->renders_forces()) {
    throw UnsupportedError("surface type '" + scene.surface_id +
                           "' cannot render forces yet: " + scene.surface->limitation());
  }
  const auto start = Clock::now();
  PreparedScene prepared;
  prepared.surface = scene.surface;
  prepared.rotational = scene.surface->rotational();
  prepared.rng.seed(scene.run.seed);

  SkinModelShapes shapes = GenerateSkinModelShapes(scene, prepared.rng);
  prepared.discretize_seconds = shapes.discretize_seconds;
  prepared.generate_seconds = shapes.generate_seconds;
  prepared.inner_sms = std::make_unique<SkinModelShape>(std::move(shapes.inner));
  prepared.outer_sms = std::make_unique<SkinModelShape>(std::move(shapes.outer));

  auto t = Clock::now();
  prepared.analyzer = scene.surface->MakeContactAnalyzer();
  if (!prepared.analyzer) {
    throw UnsupportedError("surface type '" + scene.surface_id + "' provides no contact analyzer");
  }
  prepared.analyzer->Prepare(scene.inner, *prepared.inner_sms, scene.outer, *prepared.outer_sms,
                             scene.model);
  prepared.law = scene.surface->MakeLaw(scene.model.law);
  prepared.law->Prepare(scene.inner, scene.outer, scene.model);
  prepared.analyze_seconds = SecondsSince(t);

  prepared.total_seconds = SecondsSince(start);
  return prepared;
}

}  // namespace fitfeel
