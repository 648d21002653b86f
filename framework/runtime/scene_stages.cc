#include "framework/runtime/scene_stages.h"

#include <array>
#include <cmath>
#include <vector>

#include "framework/runtime/joint_stage.h"
#include "framework/runtime/screw_stage.h"
#include "framework/scenario/joint_frame.h"

namespace fitfeel {

bool IsScrewScene(const Scene& scene) {
  return scene.features.empty() && scene.inner.geometry != nullptr &&
         scene.inner.geometry->lead() > 0.0;
}

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
  if (IsScrewScene(scene)) {
    ScrewStage::Options screw;
    screw.depth_origin = mating.depth_origin;
    screw.moving = scene.moving;
    screw.proxy_stiffness = mating.proxy_stiffness;
    screw.axial_load = scene.part_motion.axial_load;
    screw.turn = scene.part_motion.turn;
    screw.lead = scene.inner.geometry->lead();
    screw.tilt = Eigen::Vector2d(scene.part_motion.tilt, 0.0);
    // A hand holds the part at the scene's grip.
    const double lever = scene.part_motion.grip_lever;
    if (std::isfinite(mating.proxy_stiffness) && lever > 0.0) {
      screw.twist_stiffness = mating.proxy_stiffness * lever * lever;
    }
    stages.constrained = std::make_unique<ScrewStage>(*prepared.analyzer, *prepared.law, screw);
    return stages;
  }
  if (scene.features.empty()) {
    stages.constrained =
        std::make_unique<ConstrainedStage>(*prepared.analyzer, *prepared.law, mating);
    return stages;
  }
  std::vector<JointFeature> features;
  for (std::size_t i = 0; i < scene.features.size(); ++i) {
    const MatingFeature& feature = scene.features[i];
    JointFeature f;
    f.analyzer = i == 0 ? prepared.analyzer.get() : prepared.more_features[i - 1].analyzer.get();
    f.law = i == 0 ? prepared.law.get() : prepared.more_features[i - 1].law.get();
    f.moving = feature.moving;
    const std::array<Eigen::Vector2d, 2>& deviation = prepared.position_deviations.at(i);
    const Role fixed = feature.moving == Role::kInner ? Role::kOuter : Role::kInner;
    f.moving_axis = FeatureAxis(feature, feature.moving, deviation);
    f.fixed_axis = FeatureAxis(feature, fixed, deviation);
    f.angle = feature.placement.angle;
    f.engages_after = feature.placement.engages_after;
    if (i > 0) {
      f.lead_in = feature.surface->MakeLeadIn(feature.inner, feature.outer);
      // A hand meets the lead-in through the god object's spring, as it meets the datum's; a
      // robot meets it as stiff as the feature's contact (the datum's where the feature's is the
      // law's own, `auto`).
      const double contact = feature.model.contact_stiffness > 0.0 ? feature.model.contact_stiffness
                                                                   : scene.model.contact_stiffness;
      f.lead_in_stiffness =
          std::isfinite(mating.proxy_stiffness) ? mating.proxy_stiffness : contact;
    }
    features.push_back(f);
  }
  JointStage::Options joint;
  joint.depth_origin = mating.depth_origin;
  joint.proxy_stiffness = mating.proxy_stiffness;
  stages.constrained = std::make_unique<JointStage>(std::move(features), joint);
  return stages;
}

}  // namespace fitfeel
