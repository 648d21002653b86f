#pragma once

#include <memory>

#include "framework/core/export.h"
#include "framework/device/device.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

// The two stages of a prepared scene for a device of `spec` (what `fitfeel run`, the C interface
// and the scene benchmark run):
//  - positioning: the surface type's lead-in (a god object guided by its chamfers) or else its
//    coarse meshes, with k_free = FreeMotionStiffness(model.contact_stiffness, spec);
//  - constrained: mating depth counted from the positioning stage's depth origin, and the part a
//    god object across the axis coupled by k_free when the device renders a finite stiffness
//    (a hand at a haptic device); a device without a limit (a robot) holds it rigidly.
// A several-feature scene's positioning is its first (datum) feature's, and its constrained
// stage a JointStage over every feature with the same depth origin and coupling.
// The stages refer into `prepared`, which must outlive them. Throws UserError for what the
// surface plugin refuses.
struct FITFEEL_API SceneStages {
  std::unique_ptr<PositioningStage> positioning;
  // A ConstrainedStage, or for a several-feature scene a JointStage over its features.
  std::unique_ptr<Stage> constrained;
};
// A scene of one thread (its geometry has a lead): its constrained stage is a ScrewStage, and its
// outputs carry the joint's preload and torques.
FITFEEL_API bool IsScrewScene(const Scene& scene);

FITFEEL_API SceneStages MakeSceneStages(const Scene& scene, const PreparedScene& prepared,
                                        const DeviceSpec& spec);

}  // namespace fitfeel
