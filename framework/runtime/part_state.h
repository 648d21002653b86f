#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"

namespace fitfeel {

// The moving part as the stages see it each tick, in the scene frame (y is the mating axis): the
// plant's state, not the device's. PartMotion::Place makes it from what the device reports (its
// pose and velocities) and the scene's part motion (where the part floats across the axis and the
// load it settles under); the safety chain's coupling may put it at its proxy instead.
struct PartState {
  double time = 0.0;                        // s since the start of the run
  Eigen::Vector3d position{0.0, 0.0, 0.0};  // the leading end
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity{0.0, 0.0, 0.0};
  Eigen::Vector3d angular_velocity{0.0, 0.0, 0.0};
  // The radial load (x, z components, N) the constrained stage settles the part under: the
  // scene's part_motion.radial_load once the part is past the entrance where its radial motion is
  // quasi-static; zero otherwise (held, dynamic, or still outside).
  Eigen::Vector2d settle_load{0.0, 0.0};
  // About the mating axis (several-feature scenes): whether the part turns under the contact's
  // torque (else it keeps the device's twist), and the torque applied about +y then, N*m.
  bool free_rotation = false;
  double applied_torque = 0.0;
};

// The moving part's pose in the fixed part's mating frame (positioning_stage.h gives the
// convention): depth = y of the leading end, offset = its (x, z), angle = the twist of the
// orientation about y, tilt = the rest of it (the swing that turns y onto the part's axis).
FITFEEL_API MatingPose MatingPoseOf(const PartState& part) noexcept;

}  // namespace fitfeel
