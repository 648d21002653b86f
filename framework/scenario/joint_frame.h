#pragma once

// The joint frame of a several-feature scene (docs/assemblies.md): its turn about the axis and
// where each feature's sides lie in it, one definition for the loader, the joint stage and the
// viewer.

#include <array>
#include <cmath>

#include <Eigen/Core>

#include "framework/model/gps_spec.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

// R(angle) about +y, (x, z) -> (x c + z s, -x s + z c), given the angle's cosine c and sine s: a
// tick turns by the same angles many times and takes them once.
inline Eigen::Vector2d TurnAboutAxis(const Eigen::Vector2d& v, double c, double s) {
  return {c * v.x() + s * v.y(), -s * v.x() + c * v.y()};
}
inline Eigen::Vector2d TurnAboutAxis(const Eigen::Vector2d& v, double angle) {
  return TurnAboutAxis(v, std::cos(angle), std::sin(angle));
}

// Where an earlier step of a sequence left the part on a feature's fixed side, turned from the
// feature's frame into the joint frame; zero outside a sequence.
inline Eigen::Vector2d SeatInJointFrame(const FeaturePlacement& placement) {
  return TurnAboutAxis(placement.seat, placement.angle);
}

// The axis of `feature`'s `side` in the joint frame, the moving body at its zero pose: the
// feature's `at` plus that side's drawn position deviation (PreparedScene::position_deviations:
// inner side, outer side), and on the fixed side its seat.
inline Eigen::Vector2d FeatureAxis(const MatingFeature& feature, Role side,
                                   const std::array<Eigen::Vector2d, 2>& deviation) {
  const Eigen::Vector2d drawn = feature.placement.at + deviation[side == Role::kInner ? 0 : 1];
  return side == feature.moving ? drawn
                                : Eigen::Vector2d(drawn + SeatInJointFrame(feature.placement));
}

}  // namespace fitfeel
