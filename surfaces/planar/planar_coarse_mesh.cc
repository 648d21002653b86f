#include "surfaces/planar/planar_coarse_mesh.h"

#include <algorithm>
#include <cmath>

#include "surfaces/planar/planar_geometry.h"

namespace fitfeel::planar {
namespace {

double Zone(const PartSpec& part) {
  return std::abs(part.size.upper_deviation - part.size.lower_deviation);
}

// Below this a gap is lost in the rounding of poses a few centimetres from the origin.
constexpr double kMinGap = 1e-7;  // m

}  // namespace

CoarseMeshes MakePlanarCoarseMeshes(const PartSpec& inner, const PartSpec& outer) {
  const PlanarGeometry& key = PlanarGeometryOf(inner);
  const PlanarGeometry& slot = PlanarGeometryOf(outer);
  const double b = key.width();
  const bool square = key.faces() == 4;
  const double half_height = 0.5 * (square ? b : key.height());
  CoarseMeshes meshes;
  meshes.inner = MakeBox(Eigen::Vector3d(-0.5 * b, -key.length(), -half_height),
                         Eigen::Vector3d(0.5 * b, 0.0, half_height));
  const double s = 0.5 * slot.width() + std::max(kMinGap, 0.25 * (Zone(inner) + Zone(outer)));
  const double w = b;  // wall thickness
  const double reach = square ? s + w : 0.5 * std::max(key.height(), slot.height()) + w;
  const double length = slot.length();
  AppendMesh(MakeBox(Eigen::Vector3d(s, 0.0, -reach), Eigen::Vector3d(s + w, length, reach)),
             &meshes.outer);
  AppendMesh(MakeBox(Eigen::Vector3d(-s - w, 0.0, -reach), Eigen::Vector3d(-s, length, reach)),
             &meshes.outer);
  if (square) {
    AppendMesh(MakeBox(Eigen::Vector3d(-s - w, 0.0, s), Eigen::Vector3d(s + w, length, s + w)),
               &meshes.outer);
    AppendMesh(MakeBox(Eigen::Vector3d(-s - w, 0.0, -s - w), Eigen::Vector3d(s + w, length, -s)),
               &meshes.outer);
  }
  return meshes;
}

}  // namespace fitfeel::planar
