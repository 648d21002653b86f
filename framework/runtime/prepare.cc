#include "framework/runtime/prepare.h"

#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

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
PreparedScene::~PreparedScene() { rest.reset(); }
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

void PreparedScene::FinishPreparing() {
  if (!rest) return;
  const double whole = rest->Finish();
  rest.reset();
  analyze_seconds += whole - ready_seconds;
  total_seconds = whole;
}

namespace {

SkinModelShapes GenerateShapes(const SurfaceType& surface, const std::string& surface_id,
                               const PartSpec& inner, const PartSpec& outer,
                               const ModelSettings& model, Rng& rng) {
  // One discretizer and generator for both parts: the surface type decides the grid of each part
  // from its own geometry.
  SkinModelShapes shapes;
  auto t = Clock::now();
  const auto discretizer = surface.MakeDiscretizer();
  const auto generator = surface.MakeVariationGenerator();
  if (!discretizer || !generator) {
    throw UnsupportedError("surface type '" + surface_id +
                           "' provides no discretizer or variation generator");
  }
  if (model.options) generator->Configure(*model.options);
  const SurfaceGrid inner_grid = discretizer->Discretize(inner, model.resolution);
  const SurfaceGrid outer_grid = discretizer->Discretize(outer, model.resolution);
  shapes.discretize_seconds = SecondsSince(t);
  t = Clock::now();
  // A measured part takes no draw: the other part's draws are those it gets with the same seed
  // when it comes first, not otherwise (docs/measured-parts.md).
  auto shape = [&](const PartSpec& part, const SurfaceGrid& grid) {
    return part.measured ? MeasuredSkinModelShape(*part.measured, grid, part.size.nominal / 2.0)
                         : generator->Generate(part, grid, model.texture, rng);
  };
  shapes.inner = shape(inner, inner_grid);
  shapes.outer = shape(outer, outer_grid);
  shapes.generate_seconds = SecondsSince(t);
  return shapes;
}

// Uniform over the disc of diameter `zone` (ISO 1101's cylindrical position zone seen along the
// axis): radius zone/2 sqrt(u), direction 2 pi v.
Eigen::Vector2d DrawInZone(double zone, Rng& rng) {
  const double u = UniformDraw(rng);
  const double v = UniformDraw(rng);
  const double r = 0.5 * zone * std::sqrt(u), phi = 2.0 * M_PI * v;
  return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace

PreparedFeature::PreparedFeature() = default;
PreparedFeature::~PreparedFeature() = default;
PreparedFeature::PreparedFeature(PreparedFeature&&) noexcept = default;
PreparedFeature& PreparedFeature::operator=(PreparedFeature&&) noexcept = default;

SkinModelShapes GenerateSkinModelShapes(const Scene& scene, Rng& rng) {
  if (!scene.surface) {
    throw UserError("scene '" + scene.name + "' has no surface type '" + scene.surface_id + "'");
  }
  return GenerateShapes(*scene.surface, scene.surface_id, scene.inner, scene.outer, scene.model,
                        rng);
}

SkinModelShapes GenerateSkinModelShapes(const MatingFeature& feature, Rng& rng) {
  if (!feature.surface) {
    throw UserError("feature '" + feature.name + "' has no surface type '" + feature.surface_id +
                    "'");
  }
  return GenerateShapes(*feature.surface, feature.surface_id, feature.inner, feature.outer,
                        feature.model, rng);
}

std::vector<std::array<Eigen::Vector2d, 2>> DrawPositionDeviations(const Scene& scene, Rng& rng) {
  std::vector<std::array<Eigen::Vector2d, 2>> deviations;
  deviations.reserve(scene.features.size());
  for (const MatingFeature& feature : scene.features) {
    deviations.push_back({DrawInZone(feature.placement.inner_position, rng),
                          DrawInZone(feature.placement.outer_position, rng)});
  }
  return deviations;
}

namespace {

// Prepare's and PrepareProgressive's: `progressive` null prepares whole.
PreparedScene PrepareScene(const Scene& scene, SharedPrepare* shared, double reach,
                           double angular_reach, const ProgressiveSettings* progressive) {
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
  ModelSettings model = scene.model;
  model.reach = reach;
  model.angular_reach = angular_reach;
  if (const std::optional<Eigen::Vector2d> tilt =
          scene.device ? scene.device->held_tilt() : std::nullopt) {
    model.held_tilt = *tilt;
    model.held_tilt_stiffness = scene.device->held_tilt_stiffness();
    if (std::isfinite(model.held_tilt_stiffness) && !prepared.analyzer->takes_compliant_tilt()) {
      throw UnsupportedError("scene '" + scene.name + "': surface type '" + scene.surface_id +
                             "' models a part held rigidly at its tilt, not a compliant hold; "
                             "remove the hand's tilt_stiffness");
    }
    // A tilt the analyzer would ignore renders an aligned part while the summary says tilted.
    if (!prepared.analyzer->takes_held_tilt()) {
      throw UnsupportedError("scene '" + scene.name + "': the device holds the part tilted, and " +
                             "surface type '" + scene.surface_id +
                             "' models an aligned part only; remove the device's tilt");
    }
    if (scene.moving != Role::kInner || scene.features.size() > 1) {
      throw UnsupportedError("scene '" + scene.name + "': a held tilt is modelled for a moving " +
                             "inner part of a one-feature scene; remove the device's tilt");
    }
  }
  // Each analyzer whole, or ready to touch and the rest left to the worker.
  auto prepare = [&](ContactAnalyzer& analyzer, const PartSpec& inner,
                     const SkinModelShape& inner_sms, const PartSpec& outer,
                     const SkinModelShape& outer_sms, const ModelSettings& settings) {
    if (progressive == nullptr) {
      analyzer.Prepare(inner, inner_sms, outer, outer_sms, settings, shared);
    } else {
      analyzer.PrepareStart(inner, inner_sms, outer, outer_sms, settings, shared,
                            progressive->ready_depth);
    }
  };
  prepare(*prepared.analyzer, scene.inner, *prepared.inner_sms, scene.outer, *prepared.outer_sms,
          model);
  prepared.law = scene.surface->MakeLaw(scene.model.law);
  prepared.law->Prepare(scene.inner, scene.outer, scene.model);
  prepared.analyze_seconds = SecondsSince(t);

  for (std::size_t i = 1; i < scene.features.size(); ++i) {
    const MatingFeature& feature = scene.features[i];
    if (!feature.surface->renders_forces()) {
      throw UnsupportedError("surface type '" + feature.surface_id +
                             "' cannot render forces yet: " + feature.surface->limitation());
    }
    SkinModelShapes more = GenerateSkinModelShapes(feature, prepared.rng);
    prepared.discretize_seconds += more.discretize_seconds;
    prepared.generate_seconds += more.generate_seconds;
    t = Clock::now();
    PreparedFeature p;
    p.inner_sms = std::make_unique<SkinModelShape>(std::move(more.inner));
    p.outer_sms = std::make_unique<SkinModelShape>(std::move(more.outer));
    p.analyzer = feature.surface->MakeContactAnalyzer();
    if (!p.analyzer) {
      throw UnsupportedError("surface type '" + feature.surface_id +
                             "' provides no contact analyzer");
    }
    prepare(*p.analyzer, feature.inner, *p.inner_sms, feature.outer, *p.outer_sms, feature.model);
    p.law = feature.surface->MakeLaw(feature.model.law);
    p.law->Prepare(feature.inner, feature.outer, feature.model);
    prepared.analyze_seconds += SecondsSince(t);
    prepared.more_features.push_back(std::move(p));
  }
  prepared.position_deviations = DrawPositionDeviations(scene, prepared.rng);

  prepared.total_seconds = SecondsSince(start);
  prepared.ready_seconds = prepared.total_seconds;
  if (progressive != nullptr) {
    std::vector<ContactAnalyzer*> analyzers{prepared.analyzer.get()};
    for (PreparedFeature& f : prepared.more_features) analyzers.push_back(f.analyzer.get());
    prepared.rest = std::make_unique<PrepareWorker>(std::move(analyzers), start,
                                                    progressive->worker, progressive->pace);
  }
  return prepared;
}

}  // namespace

PreparedScene Prepare(const Scene& scene, SharedPrepare* shared, double reach,
                      double angular_reach) {
  return PrepareScene(scene, shared, reach, angular_reach, nullptr);
}

PreparedScene PrepareProgressive(const Scene& scene, const ProgressiveSettings& settings,
                                 SharedPrepare* shared, double reach, double angular_reach) {
  return PrepareScene(scene, shared, reach, angular_reach, &settings);
}

}  // namespace fitfeel
