#pragma once

#include <cmath>

#include "framework/collision/coarse_mesh.h"

namespace fitfeel::test_support {

// The tube as one solid (its walls and annular faces, not convex), as a plugin may give it: the
// collider takes such a mesh to FCL's hierarchies. MakeTube gives convex sectors instead.
inline TriangleMesh SolidTube(double inner_radius, double outer_radius, double y0, double y1,
                              int n) {
  TriangleMesh mesh;
  for (const double radius : {outer_radius, inner_radius / std::cos(M_PI / n)}) {
    for (const double y : {y0, y1}) {
      for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        mesh.vertices.emplace_back(radius * std::cos(a), y, radius * std::sin(a));
      }
    }
  }
  const int outer_low = 0, outer_high = n, inner_low = 2 * n, inner_high = 3 * n;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.triangles.emplace_back(outer_low + i, outer_high + i, outer_high + j);
    mesh.triangles.emplace_back(outer_low + i, outer_high + j, outer_low + j);
    mesh.triangles.emplace_back(inner_low + i, inner_high + j, inner_high + i);
    mesh.triangles.emplace_back(inner_low + i, inner_low + j, inner_high + j);
    mesh.triangles.emplace_back(inner_low + i, outer_low + i, outer_low + j);
    mesh.triangles.emplace_back(inner_low + i, outer_low + j, inner_low + j);
    mesh.triangles.emplace_back(inner_high + i, outer_high + j, outer_high + i);
    mesh.triangles.emplace_back(inner_high + i, inner_high + j, outer_high + j);
  }
  return mesh;
}

}  // namespace fitfeel::test_support
