#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// The assembly space of one insertion depth (paper section 3.1): all overlapping cross-sections
// share the n direction angles beta_j, so the positions the moving axis may take form the convex
// polygon { p : p . u_j <= h_j } with h_j = min_i S_T(i, j). These helpers build its vertices at
// prepare time and answer the per-tick queries on them without allocating.

// Half-plane intersection in O(n) after sorting by angle (the deque method). `angle`, `h` hold n
// constraints p . (cos angle, sin angle) <= h. A bounding box of +-`bound` keeps the result
// bounded when the normals do not surround the origin. Returns false when the intersection is
// empty (interference); otherwise `vertices` holds it counter-clockwise (a single point may come
// back as several coincident vertices).
FITFEEL_API bool IntersectHalfPlanes(const std::vector<double>& angle, const std::vector<double>& h,
                         double bound, std::vector<Eigen::Vector2d>* vertices);

// Nearest point of the polygon to x (x itself when inside). O(vertices), no allocation.
FITFEEL_API Eigen::Vector2d ProjectOntoPolygon(const Eigen::Vector2d* vertices, int count,
                                   const Eigen::Vector2d& x) noexcept;

// S_A(gamma): distance from the origin to the polygon's boundary along direction `direction`
// (unit). Zero when the origin is not inside the polygon. O(vertices), no allocation.
FITFEEL_API double RayExtent(const Eigen::Vector2d* vertices, int count,
                 const Eigen::Vector2d& direction) noexcept;

// Area centroid (vertex mean for a degenerate polygon): a point inside that tends to the single
// remaining point as the polygon shrinks, which keeps forces continuous at the clearance /
// interference boundary.
FITFEEL_API Eigen::Vector2d PolygonCentroid(const Eigen::Vector2d* vertices, int count) noexcept;

}  // namespace fitfeel
