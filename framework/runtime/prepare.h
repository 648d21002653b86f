#pragma once

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/model/shared_prepare.h"
#include "framework/model/skin_model_shape.h"
#include "framework/model/surface_type.h"
#include "framework/model/variation_generator.h"
#include "framework/runtime/prepare_worker.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

// A mating feature of a several-feature scene after the datum one, prepared (its skin model
// shapes, analyzer and law).
struct FITFEEL_API PreparedFeature {
  PreparedFeature();
  ~PreparedFeature();
  PreparedFeature(PreparedFeature&&) noexcept;
  PreparedFeature& operator=(PreparedFeature&&) noexcept;

  std::unique_ptr<SkinModelShape> inner_sms;
  std::unique_ptr<SkinModelShape> outer_sms;
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
};

// Everything a run needs that depends only on the scene, built once before the tick loop: the skin
// model shapes of both parts, the contact analyzer's tables and the prepared law. The stages hold
// references into it, so it must outlive them (it is move-only and keeps its objects on the heap,
// so moving it does not invalidate those references).
struct FITFEEL_API PreparedScene {
  PreparedScene();
  ~PreparedScene();
  PreparedScene(PreparedScene&&) noexcept;
  PreparedScene& operator=(PreparedScene&&) noexcept;

  // A progressive prepare (PrepareProgressive): the analyzers' depth steps left after the ready
  // ones, prepared on its worker thread or by FinishPreparing; null once whole, and for a whole
  // prepare. The first member, so that it stops before anything it prepares is replaced (a move
  // assigns members in order) or destroyed (the destructor stops it first).
  std::unique_ptr<PrepareWorker> rest;
  // Prepares what the rest has left on the calling thread (stopping the worker first), so that
  // every table is whole, and sets analyze_seconds and total_seconds to include it. Rethrows what
  // the worker threw. Nothing to do after a whole prepare.
  void FinishPreparing();

  // The scene's only random generator, seeded from run.seed. Prepare draws the inner part's skin
  // model shape first, then the outer part's; whatever is prepared later (a stage, a device
  // script) continues from here, so a scene and seed give the same run bit for bit.
  Rng rng;
  std::shared_ptr<const SurfaceType> surface;  // keeps the surface plugin's objects alive
  std::unique_ptr<SkinModelShape> inner_sms;
  std::unique_ptr<SkinModelShape> outer_sms;
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
  bool rotational = false;  // the constrained motion is a rotation (torque is reported)
  // A several-feature scene: the features after the datum one (Scene::features[1...]), drawn and
  // prepared in that order after it, and then where each feature's axis lies off its nominal
  // place on the inner and the outer side (drawn within its position tolerance, joint frame, m;
  // zero for the datum feature). Empty for a one-feature scene.
  std::vector<PreparedFeature> more_features;
  std::vector<std::array<Eigen::Vector2d, 2>> position_deviations;

  // Wall time of each prepare step, s. A progressive prepare's analyze and total seconds count
  // its rest once FinishPreparing has run.
  double discretize_seconds = 0.0;
  double generate_seconds = 0.0;
  double analyze_seconds = 0.0;
  double total_seconds = 0.0;
  // Wall time until the scene was ready to touch, s: a progressive prepare's ready steps, a whole
  // prepare's total.
  double ready_seconds = 0.0;
};

// A part whose leading end starts at or before the entrance meets the depth steps just past it
// first: a progressive prepare has them ready before the scene is handed over, m (a tenth of a
// second of a hand at 10 mm/s; a few of the cylinder's steps).
inline constexpr double kReadyDepth = 1e-3;

// How PrepareProgressive leaves the analyzers' depth tables.
struct ProgressiveSettings {
  // Every analyzer is ready to this depth past first contact, m, when PrepareProgressive returns.
  double ready_depth = kReadyDepth;
  // The rest on a worker thread the prepared scene owns (a run in real time); false: the caller
  // finishes it (PreparedScene::FinishPreparing; a run in virtual time, before its first tick).
  bool worker = true;
  // Test hook (may be empty): asked by the worker before each step; while it answers false the
  // worker waits.
  std::function<bool()> pace;
};

// Both parts' skin model shapes, drawn as every command draws them.
struct SkinModelShapes {
  SkinModelShape inner;
  SkinModelShape outer;
  double discretize_seconds = 0.0;
  double generate_seconds = 0.0;
};

// Discretizes both parts, then draws the inner part's skin model shape and then the outer part's
// from `rng`, with one variation generator configured with the scenario's model.options. The
// order of draws is part of the determinism contract: `fitfeel run`, `sms` and `plot sms` call
// this so that the same scene and seed give the same shapes everywhere. Works for surface types
// without a law too.
FITFEEL_API SkinModelShapes GenerateSkinModelShapes(const Scene& scene, Rng& rng);
// The same for one feature of a several-feature scene.
FITFEEL_API SkinModelShapes GenerateSkinModelShapes(const MatingFeature& feature, Rng& rng);

// Where each feature's axis lies off its nominal place on its inner and its outer side, drawn
// within its position tolerance (joint frame, m): inner side then outer, feature by feature, zero
// for a side without a tolerance (the datum feature's), which still takes its draws. Prepare
// draws these last, after every feature's skin model shapes; the viewer draws them the same way
// so that it shows the run's parts. Empty for a one-feature scene.
FITFEEL_API std::vector<std::array<Eigen::Vector2d, 2>> DrawPositionDeviations(const Scene& scene,
                                                                               Rng& rng);

// Builds the prepared scene: seeds the generator from scene.run.seed, discretizes and generates
// the skin model shape of the inner part and then of the outer part with the surface's
// Discretizer and VariationGenerator, prepares the contact analyzer and the law. A several-feature
// scene then does the same for each further feature in order, and last draws the features'
// positions (inner side, then outer, feature by feature). Throws
// UnsupportedError for a surface type that cannot render forces, UserError for anything the
// surface plugin refuses. `shared`, when given, is what the prepares of runs of this same scene
// share (SharedPrepare: a study's pairs); the prepared scene is bit for bit the same with or
// without it.
// `reach` (m): the deepest mating depth the run's own device takes the part to
// (ModelSettings::reach), and `angular_reach` (rad) the largest turn about the axis it gives it
// (ModelSettings::angular_reach); +inf for a prepared scene that other devices may drive (a
// host's, the viewer's).
FITFEEL_API PreparedScene Prepare(const Scene& scene, SharedPrepare* shared = nullptr,
                                  double reach = std::numeric_limits<double>::infinity(),
                                  double angular_reach = std::numeric_limits<double>::infinity());

// The same prepare, progressive (ContactAnalyzer::PrepareStart): every analyzer that takes it is
// prepared to settings.ready_depth, the rest is left to PreparedScene::rest. Its tables, once
// whole, are the same bits as Prepare's. `shared` must then outlive the rest.
FITFEEL_API PreparedScene PrepareProgressive(
    const Scene& scene, const ProgressiveSettings& settings, SharedPrepare* shared = nullptr,
    double reach = std::numeric_limits<double>::infinity(),
    double angular_reach = std::numeric_limits<double>::infinity());

}  // namespace fitfeel
