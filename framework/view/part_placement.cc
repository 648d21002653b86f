#include "framework/view/part_placement.h"

#include <cmath>

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
  if (!p.moving) {
    // The seat is in the feature's frame (scene_stages.cc turns it the same way).
    const double c = std::cos(p.angle), s = std::sin(p.angle);
    const Eigen::Vector2d& seat = feature.placement.seat;
    p.seat = Eigen::Vector2d(c * seat.x() + s * seat.y(), -s * seat.x() + c * seat.y());
  }
  p.axis = feature.placement.at + p.deviation + p.seat;
  return p;
}

Eigen::Vector3d PlaceDirection(const PartPlacement& placement, const Eigen::Vector3d& d) {
  Eigen::Vector3d v = d;
  if (placement.half_turn) v = Eigen::Vector3d(-v.x(), -v.y(), v.z());
  const double c = std::cos(placement.angle), s = std::sin(placement.angle);
  return {c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z()};
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
