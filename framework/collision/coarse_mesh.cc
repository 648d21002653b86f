#include "framework/collision/coarse_mesh.h"

#include <cmath>
#include <string>

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
// outward (away from the axis) when `outward`, inward otherwise.
void AddWallQuad(TriangleMesh* mesh, int a, int b, int i, int facets, bool outward) {
  const int j = (i + 1) % facets;
  // Angle grows from +x towards +z: (a_i, b_i, b_j) has the normal (sin, 0, 1 - cos) of a small
  // step, i.e. radially out; the reverse order points into the hole.
  if (outward) {
    mesh->triangles.emplace_back(a + i, b + i, b + j);
    mesh->triangles.emplace_back(a + i, b + j, a + j);
  } else {
    mesh->triangles.emplace_back(a + i, b + j, b + i);
    mesh->triangles.emplace_back(a + i, a + j, b + j);
  }
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
  CheckSpan("closed cylinder", y0, y1);
  CheckFacets("closed cylinder", facets);
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw UserError("closed cylinder: radius must be finite and > 0");
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(2 * facets + 2);
  mesh.triangles.reserve(4 * facets);
  const int low = AddRing(&mesh, radius, y0, facets);
  const int high = AddRing(&mesh, radius, y1, facets);
  const int low_centre = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, y0, 0.0);
  const int high_centre = low_centre + 1;
  mesh.vertices.emplace_back(0.0, y1, 0.0);
  for (int i = 0; i < facets; ++i) {
    const int j = (i + 1) % facets;
    AddWallQuad(&mesh, low, high, i, facets, /*outward=*/true);
    // Caps: the low cap faces -y, the high cap +y. From +y, angle (x to z) turns clockwise.
    mesh.triangles.emplace_back(low_centre, low + i, low + j);
    mesh.triangles.emplace_back(high_centre, high + j, high + i);
  }
  return mesh;
}

TriangleMesh MakeTube(double inner_radius, double outer_radius, double y0, double y1, int facets) {
  CheckSpan("tube", y0, y1);
  CheckFacets("tube", facets);
  const double inner_vertex_radius = inner_radius / std::cos(M_PI / facets);
  if (!(inner_radius > 0.0) || !std::isfinite(outer_radius) ||
      !(ChordalError(outer_radius, facets) + inner_vertex_radius < outer_radius)) {
    throw UserError("tube: needs 0 < inner radius and the inner polygon inside the outer one");
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(4 * facets);
  mesh.triangles.reserve(8 * facets);
  const int outer_low = AddRing(&mesh, outer_radius, y0, facets);
  const int outer_high = AddRing(&mesh, outer_radius, y1, facets);
  const int inner_low = AddRing(&mesh, inner_vertex_radius, y0, facets);
  const int inner_high = AddRing(&mesh, inner_vertex_radius, y1, facets);
  for (int i = 0; i < facets; ++i) {
    const int j = (i + 1) % facets;
    AddWallQuad(&mesh, outer_low, outer_high, i, facets, /*outward=*/true);
    AddWallQuad(&mesh, inner_low, inner_high, i, facets, /*outward=*/false);
    // Low annulus faces -y, high annulus +y.
    mesh.triangles.emplace_back(inner_low + i, outer_low + i, outer_low + j);
    mesh.triangles.emplace_back(inner_low + i, outer_low + j, inner_low + j);
    mesh.triangles.emplace_back(inner_high + i, outer_high + j, outer_high + i);
    mesh.triangles.emplace_back(inner_high + i, inner_high + j, outer_high + j);
  }
  return mesh;
}

}  // namespace fitfeel
