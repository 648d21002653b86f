#include "framework/runtime/scene_stages.h"

#include <cmath>

namespace fitfeel {

SceneStages MakeSceneStages(const Scene& scene, const PreparedScene& prepared,
                            const DeviceSpec& spec) {
  PositioningStage::Options free_motion;
  free_motion.free_stiffness =
      FreeMotionStiffness(scene.model.contact_stiffness, spec.max_stiffness);
  SceneStages stages;
  LeadIn lead_in = prepared.surface->MakeLeadIn(scene.inner, scene.outer);
  // Coarse meshes only where no lead-in takes their place (PositioningStage).
  const bool meshes = lead_in.empty();
  stages.positioning = std::make_unique<PositioningStage>(
      free_motion,
      meshes ? prepared.surface->MakeCoarseMeshes(scene.inner, scene.outer) : CoarseMeshes{},
      scene.moving, std::move(lead_in));
  ConstrainedStage::Options mating;
  mating.depth_origin = stages.positioning->depth_origin();
  mating.moving = scene.moving;
  const bool limited = spec.max_stiffness > 0.0 && std::isfinite(spec.max_stiffness);
  if (limited && free_motion.free_stiffness > 0.0) {
    mating.proxy_stiffness = free_motion.free_stiffness;
  }
  stages.constrained =
      std::make_unique<ConstrainedStage>(*prepared.analyzer, *prepared.law, mating);
  return stages;
}

}  // namespace fitfeel
