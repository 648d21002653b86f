#include "framework/collision/coarse_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

constexpr int kMinFacets = 8;
constexpr int kMaxFacets = 4096;

void CheckSpan(const char* what, double y0, double y1) {
  if (!std::isfinite(y0) || !std::isfinite(y1) || !(y0 < y1)) {
    throw UserError(std::string(what) + ": needs finite ends y0 < y1");
  }
}

void CheckFacets(const char* what, int facets) {
  if (facets < 3 || facets > kMaxFacets) {
    throw UserError(std::string(what) + ": facet count must be in [3, " +
                    std::to_string(kMaxFacets) + "], got " + std::to_string(facets));
  }
}

// Appends a ring of `facets` vertices at `radius` and height y; returns the first index.
int AddRing(TriangleMesh* mesh, double radius, double y, int facets) {
  const int first = static_cast<int>(mesh->vertices.size());
  for (int i = 0; i < facets; ++i) {
    const double angle = 2.0 * M_PI * i / facets;
    mesh->vertices.emplace_back(radius * std::cos(angle), y, radius * std::sin(angle));
  }
  return first;
}

// Quad between ring a (at lower y) and ring b (higher y), facet i, with its normal pointing
// outward (away from the axis).
void AddWallQuad(TriangleMesh* mesh, int a, int b, int i, int facets) {
  const int j = (i + 1) % facets;
  // Angle grows from +x towards +z: (a_i, b_i, b_j) has the normal (sin, 0, 1 - cos) of a small
  // step, i.e. radially out.
  mesh->triangles.emplace_back(a + i, b + i, b + j);
  mesh->triangles.emplace_back(a + i, b + j, a + j);
}

// The planar quad of corners first + corner[0..3] (in cyclic order) of a convex solid whose
// centre is `centre`, as two triangles wound counter-clockwise from outside (seen from the
// centre, whichever way the corners were listed).
void AddConvexQuad(TriangleMesh* mesh, int first, const std::array<int, 4>& corner,
                   const Eigen::Vector3d& centre) {
  std::array<int, 4> q;
  for (int k = 0; k < 4; ++k) {
    q[static_cast<std::size_t>(k)] = first + corner[static_cast<std::size_t>(k)];
  }
  auto at = [&](int k) {
    return mesh->vertices[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])];
  };
  const Eigen::Vector3d normal = (at(1) - at(0)).cross(at(2) - at(0));
  if (normal.dot(at(0) - centre) < 0.0) std::swap(q[1], q[3]);
  mesh->triangles.emplace_back(q[0], q[1], q[2]);
  mesh->triangles.emplace_back(q[0], q[2], q[3]);
}

}  // namespace

double ChordalError(double radius, int facets) { return radius * (1.0 - std::cos(M_PI / facets)); }

int FacetsForChordalError(double radius, double max_chordal_error) {
  if (!(radius > 0.0) || !std::isfinite(radius) || !(max_chordal_error > 0.0) ||
      !std::isfinite(max_chordal_error)) {
    throw UserError("coarse mesh: radius and chordal error must be finite and > 0");
  }
  if (max_chordal_error >= radius) return kMinFacets;
  const double n = M_PI / std::acos(1.0 - max_chordal_error / radius);
  if (!(n <= kMaxFacets)) {
    throw UserError("coarse mesh: a chordal error of " + std::to_string(max_chordal_error) +
                    " m on a radius of " + std::to_string(radius) + " m needs more than " +
                    std::to_string(kMaxFacets) + " facets");
  }
  int facets = static_cast<int>(std::ceil(n - 1e-9));
  // Guard the rounding: the result must meet the bound.
  while (ChordalError(radius, facets) > max_chordal_error && facets < kMaxFacets) ++facets;
  return facets < kMinFacets ? kMinFacets : facets;
}

TriangleMesh MakeClosedCylinder(double radius, double y0, double y1, int facets) {
  return MakeClosedFrustum(radius, radius, y0, y1, facets);
}

TriangleMesh MakeClosedFrustum(double radius0, double radius1, double y0, double y1, int facets) {
  CheckSpan("closed frustum", y0, y1);
  CheckFacets("closed frustum", facets);
  if (!(radius0 > 0.0) || !std::isfinite(radius0) || !(radius1 > 0.0) || !std::isfinite(radius1)) {
    throw UserError("closed frustum: radii must be finite and > 0");
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(2 * facets + 2);
  mesh.triangles.reserve(4 * facets);
  const int low = AddRing(&mesh, radius0, y0, facets);
  const int high = AddRing(&mesh, radius1, y1, facets);
  const int low_centre = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, y0, 0.0);
  const int high_centre = low_centre + 1;
  mesh.vertices.emplace_back(0.0, y1, 0.0);
  for (int i = 0; i < facets; ++i) {
    const int j = (i + 1) % facets;
    AddWallQuad(&mesh, low, high, i, facets);
    // Caps: the low cap faces -y, the high cap +y. From +y, angle (x to z) turns clockwise.
    mesh.triangles.emplace_back(low_centre, low + i, low + j);
    mesh.triangles.emplace_back(high_centre, high + j, high + i);
  }
  return mesh;
}

TriangleMesh MakeTube(double inner_radius, double outer_radius, double y0, double y1, int facets) {
  return MakeTaperedTube(inner_radius, inner_radius, outer_radius, y0, y1, facets);
}

TriangleMesh MakeTaperedTube(double inner_radius0, double inner_radius1, double outer_radius,
                             double y0, double y1, int facets) {
  CheckSpan("tube", y0, y1);
  CheckFacets("tube", facets);
  const double widest = std::max(inner_radius0, inner_radius1) / std::cos(M_PI / facets);
  if (!(inner_radius0 > 0.0) || !(inner_radius1 > 0.0) || !std::isfinite(outer_radius) ||
      !(ChordalError(outer_radius, facets) + widest < outer_radius)) {
    throw UserError("tube: needs 0 < inner radii and the inner polygon inside the outer one");
  }
  // One closed, convex sector per facet: its bore facet, its outer facet and the two planes
  // through the axis at the facet's ends (a tube as a whole is not convex; its sectors are, and a
  // collider separates convex solids cheaply).
  TriangleMesh mesh;
  mesh.vertices.reserve(8 * static_cast<std::size_t>(facets));
  mesh.triangles.reserve(12 * static_cast<std::size_t>(facets));
  const double c = std::cos(M_PI / facets);
  for (int i = 0; i < facets; ++i) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (const auto& [y, inner] : {std::pair{y0, inner_radius0}, std::pair{y1, inner_radius1}}) {
      for (int k : {i, i + 1}) {
        const double angle = 2.0 * M_PI * (k % facets) / facets;
        const Eigen::Vector3d direction(std::cos(angle), 0.0, std::sin(angle));
        mesh.vertices.push_back(inner / c * direction + Eigen::Vector3d(0.0, y, 0.0));
        mesh.vertices.push_back(outer_radius * direction + Eigen::Vector3d(0.0, y, 0.0));
      }
    }
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 8; ++k) centre += mesh.vertices[static_cast<std::size_t>(first + k)] / 8.0;
    // Corners: 0 / 1 inner / outer at the facet's start, 2 / 3 at its end, at y0; 4-7 at y1.
    AddConvexQuad(&mesh, first, {0, 1, 3, 2}, centre);  // low end
    AddConvexQuad(&mesh, first, {4, 5, 7, 6}, centre);  // high end
    AddConvexQuad(&mesh, first, {0, 2, 6, 4}, centre);  // bore facet
    AddConvexQuad(&mesh, first, {1, 3, 7, 5}, centre);  // outer facet
    AddConvexQuad(&mesh, first, {0, 1, 5, 4}, centre);  // plane at the facet's start
    AddConvexQuad(&mesh, first, {2, 3, 7, 6}, centre);  // plane at its end
  }
  return mesh;
}

TriangleMesh MakeBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  if (!low.allFinite() || !high.allFinite() || !(low.array() < high.array()).all()) {
    throw UserError("box: needs finite corners with low < high on every axis");
  }
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.emplace_back((k & 1) ? high.x() : low.x(), (k & 2) ? high.y() : low.y(),
                               (k & 4) ? high.z() : low.z());
  }
  // Two triangles per face, counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    mesh.triangles.emplace_back(f[0], f[1], f[2]);
    mesh.triangles.emplace_back(f[0], f[2], f[3]);
  }
  return mesh;
}

void AppendMesh(const TriangleMesh& part, TriangleMesh* mesh) {
  const int offset = static_cast<int>(mesh->vertices.size());
  mesh->vertices.insert(mesh->vertices.end(), part.vertices.begin(), part.vertices.end());
  for (const Eigen::Vector3i& t : part.triangles) {
    mesh->triangles.push_back(t + Eigen::Vector3i::Constant(offset));
  }
}

}  // namespace fitfeel
