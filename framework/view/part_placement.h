#pragma once

#include <array>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/render_mesh.h"
#include "framework/scenario/scene.h"

namespace fitfeel::view {

// Where the viewer draws one part of a several-feature scene (docs/assemblies.md). Such a scene is
// drawn in the joint frame: the fixed body's, y along the insertion (the moving body comes from
// y < 0), its origin on the datum feature's axis at that feature's entrance. A part's render mesh
// comes in its own mating frame (framework/model/render_mesh.h: an inner part's leading end at the
// origin and its body at y <= 0, an outer part's entrance at y = 0 and its body beyond); PlaceMesh
// puts it into the joint frame, the moving body's parts where they lie at the body's zero pose, so
// that the page moves all of them with the one transform of the body's pose each tick: turned by
// the twist theta about the joint's axis (y), then moved by (offset x, depth, offset z), the
// JointStage's R(theta) p + o.
struct PartPlacement {
  // The part's axis (x, z) in the joint frame: the feature's `at` plus `deviation` plus `seat`, m.
  Eigen::Vector2d axis{0.0, 0.0};
  // Of it, the deviation drawn within the part's position tolerance, m (the page draws it
  // exaggerated with the skin model deviations).
  Eigen::Vector2d deviation{0.0, 0.0};
  // Of it, where an earlier step of a sequence left the part that this fixed part is
  // (FeaturePlacement::seat, turned into the joint frame as the JointStage turns it), m; zero on
  // the moving body and outside a sequence. It is that step's offset across its axis, which the
  // page draws exaggerated as it draws the moving body's.
  Eigen::Vector2d seat{0.0, 0.0};
  double angle = 0.0;  // the feature's own frame turned about +y from the joint frame, rad
  // How far the part lies back along its own axis, away from its mating end, m: a feature's inner
  // part by its `engages_after` (its leading end lies that much further back).
  double setback = 0.0;
  // Where a feature's outer part is on the moving body, the feature's frame is its inner part's
  // turned half a turn about z (positioning_stage.h, AnalyzerPose), so that the moving part
  // always advances along +y: both parts' meshes turn by it.
  bool half_turn = false;
  bool moving = false;  // on the moving body
};

// The placement of `feature`'s `part` (its inner or its outer side), with the feature's drawn
// position deviations (PreparedScene::position_deviations: inner side, outer side) and, on its
// fixed side, its seat.
FITFEEL_API PartPlacement PlacementOf(const MatingFeature& feature, Role part,
                                      const std::array<Eigen::Vector2d, 2>& deviation);

// A point of the part's mating frame in the joint frame (a moving part's at the body's zero pose):
// moved back by the setback, turned half a turn about z where the placement says so, turned by the
// angle about y, R(angle) (x, z) = (x cos + z sin, -x sin + z cos), and moved to the axis.
FITFEEL_API Eigen::Vector3d PlacePoint(const PartPlacement& placement,
                                       const Eigen::Vector3d& point);
// A direction of the part's mating frame in the joint frame: turned as PlacePoint turns, not moved.
FITFEEL_API Eigen::Vector3d PlaceDirection(const PartPlacement& placement,
                                           const Eigen::Vector3d& direction);
// The render mesh with every corner placed and every direction turned (an empty mesh stays empty).
FITFEEL_API RenderMesh PlaceMesh(const PartPlacement& placement, const RenderMesh& mesh);

}  // namespace fitfeel::view
