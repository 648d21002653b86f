#include "framework/view/part_placement.h"

#include <cmath>

#include "framework/scenario/joint_frame.h"

namespace fitfeel::view {

PartPlacement PlacementOf(const MatingFeature& feature, Role part,
                          const std::array<Eigen::Vector2d, 2>& deviation) {
  const bool inner = part == Role::kInner;
  PartPlacement p;
  p.deviation = deviation[inner ? 0 : 1];
  p.angle = feature.placement.angle;
  p.setback = inner ? feature.placement.engages_after : 0.0;
  p.half_turn = feature.moving == Role::kOuter;
  p.moving = feature.moving == part;
  if (!p.moving) p.seat = SeatInJointFrame(feature.placement);
  p.axis = FeatureAxis(feature, part, deviation);
  return p;
}

Eigen::Vector3d PlaceDirection(const PartPlacement& placement, const Eigen::Vector3d& d) {
  Eigen::Vector3d v = d;
  if (placement.half_turn) v = Eigen::Vector3d(-v.x(), -v.y(), v.z());
  const Eigen::Vector2d xz = TurnAboutAxis(Eigen::Vector2d(v.x(), v.z()), placement.angle);
  return {xz.x(), v.y(), xz.y()};
}

Eigen::Vector3d PlacePoint(const PartPlacement& placement, const Eigen::Vector3d& point) {
  // The setback is along the part's own -y (towards its body), before the frame turns.
  const Eigen::Vector3d back(point.x(), point.y() - placement.setback, point.z());
  return PlaceDirection(placement, back) +
         Eigen::Vector3d(placement.axis.x(), 0.0, placement.axis.y());
}

RenderMesh PlaceMesh(const PartPlacement& placement, const RenderMesh& mesh) {
  RenderMesh out;
  out.corners.reserve(mesh.corners.size());
  out.directions.reserve(mesh.directions.size());
  for (const Eigen::Vector3d& c : mesh.corners) out.corners.push_back(PlacePoint(placement, c));
  for (const Eigen::Vector3d& d : mesh.directions) {
    out.directions.push_back(PlaceDirection(placement, d));
  }
  return out;
}

}  // namespace fitfeel::view
