#pragma once

#include <span>
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
FITFEEL_API bool IntersectHalfPlanes(std::span<const double> angle, std::span<const double> h,
                                     double bound, std::vector<Eigen::Vector2d>* vertices);

// The same for many right-hand sides over fixed directions (a depth table's columns): the
// directions' normals and their order by angle computed once. Intersect gives exactly what
// IntersectHalfPlanes gives for these angles; it is const and safe to call from several threads.
class FITFEEL_API HalfPlanes {
 public:
  HalfPlanes() = default;
  HalfPlanes(std::span<const double> angle, double bound);
  bool Intersect(std::span<const double> h, std::vector<Eigen::Vector2d>* vertices) const;

 private:
  double bound_ = 0.0;
  std::vector<Eigen::Vector2d> normal_;  // sorted by angle, the bounding box's four included
  std::vector<int> source_;              // index into h of each, -1: the box (h = bound)
};

// Nearest point of the polygon to x (x itself when inside). O(vertices), no allocation.
FITFEEL_API Eigen::Vector2d ProjectOntoPolygon(const Eigen::Vector2d* vertices, int count,
                                               const Eigen::Vector2d& x) noexcept;

// S_A(gamma): distance from the origin to the polygon's boundary along direction `direction`
// (unit). Zero when the origin is not inside the polygon. O(vertices), no allocation.
FITFEEL_API double RayExtent(const Eigen::Vector2d* vertices, int count,
                             const Eigen::Vector2d& direction) noexcept;

// Logarithmic queries for polygons the tick asks many times (one per depth step, prepared once):
// the vertices' angles about a point strictly inside, increasing from the first vertex's, turn
// "which edge faces x" into a binary search. Only for polygons with an interior.
struct PolygonFan {
  Eigen::Vector2d centre{0.0, 0.0};  // the reference point (inside)
  const double* angles = nullptr;    // count pseudo-angles, angles[0] in [0, 4), non-decreasing
  bool valid() const { return angles != nullptr; }
};

// A monotone stand-in for the angle of `d` (atan2) on [0, 4): where the ray through d meets the
// diamond |x| + |y| = 1, counted by quadrants from +x (0) through +y (1), -x (2) and -y (3); 0 for
// d = 0. A fan needs only the angles' order, and a division costs a tenth of an arctangent (four
// of which were a fifth of a hand's tick).
inline double PseudoAngle(const Eigen::Vector2d& d) noexcept {
  const double x = d.x(), y = d.y();
  if (y >= 0.0) {
    if (x >= 0.0) return x + y > 0.0 ? y / (x + y) : 0.0;
    return 1.0 - x / (y - x);
  }
  if (x < 0.0) return 2.0 - y / (-x - y);
  const double p = 3.0 + x / (x - y);
  return p < 4.0 ? p : 0.0;  // a hair below +x rounds to a whole turn, which is 0
}
inline constexpr double kPseudoTurn = 4.0;  // a whole turn in pseudo-angle

// Fills `angles` (count values) with the vertices' pseudo-angles about `centre`, unwrapped (by
// whole turns of 4); false when the polygon has no interior or `centre` is not strictly inside
// it (`angles` is then no fan).
FITFEEL_API bool FanAngles(const Eigen::Vector2d* vertices, int count,
                           const Eigen::Vector2d& centre, double* angles) noexcept;

// ProjectOntoPolygon with a fan about an interior point: the edge the segment centre-x crosses
// faces x, and the distance to the boundary falls monotonically along the chain facing x to its
// nearest point, so a walk from that edge finds it. O(log n + the walk), no allocation.
FITFEEL_API Eigen::Vector2d ProjectOntoPolygon(const Eigen::Vector2d* vertices, int count,
                                               const PolygonFan& fan,
                                               const Eigen::Vector2d& x) noexcept;

// RayExtent with a fan about the origin (which must be inside: FanAngles refuses otherwise):
// the ray leaves through the edge of its angle's wedge. O(log n), no allocation.
FITFEEL_API double RayExtent(const Eigen::Vector2d* vertices, int count, const PolygonFan& fan,
                             const Eigen::Vector2d& direction) noexcept;

// Area centroid (vertex mean for a degenerate polygon): a point inside that tends to the single
// remaining point as the polygon shrinks, which keeps forces continuous at the clearance /
// interference boundary.
FITFEEL_API Eigen::Vector2d PolygonCentroid(const Eigen::Vector2d* vertices, int count) noexcept;

}  // namespace fitfeel
