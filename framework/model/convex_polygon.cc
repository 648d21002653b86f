#include "framework/model/convex_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace fitfeel {
namespace {

struct Line {
  Eigen::Vector2d u;  // outward normal; inside is p . u <= h
  double h;
  Eigen::Vector2d dir() const { return {-u.y(), u.x()}; }  // inside lies on the left
};

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Eigen::Vector2d Intersect(const Line& a, const Line& b) {
  const double det = Cross(a.u, b.u);
  return {(a.h * b.u.y() - b.h * a.u.y()) / det, (a.u.x() * b.h - b.u.x() * a.h) / det};
}

// The deque method over lines sorted by angle.
bool IntersectSorted(const std::vector<Line>& lines, double bound,
                     std::vector<Eigen::Vector2d>* vertices) {
  vertices->clear();
  // Lengths here are metres of micrometre scale: an absolute tolerance far below any clearance.
  const double eps = 1e-15 * std::max(1.0, bound);
  auto out = [eps](const Line& l, const Eigen::Vector2d& p) { return p.dot(l.u) > l.h + eps; };

  std::vector<Line> dq(lines.size() + 1);
  int front = 0, len = 0;  // dq[front .. front+len)
  for (const Line& l : lines) {
    while (len > 1 && out(l, Intersect(dq[front + len - 1], dq[front + len - 2]))) --len;
    while (len > 1 && out(l, Intersect(dq[front], dq[front + 1]))) {
      ++front;
      --len;
    }
    if (len > 0) {
      const Line& back = dq[front + len - 1];
      if (std::abs(Cross(l.dir(), back.dir())) < 1e-12) {
        if (l.dir().dot(back.dir()) < 0.0) {
          // Anti-parallel neighbours: the strip between them is all that is left.
          if (l.h + back.h < -eps) return false;
        } else {
          if (l.h < back.h) {
            --len;
          } else {
            continue;
          }
        }
      }
    }
    dq[front + len] = l;
    ++len;
  }
  while (len > 2 && out(dq[front], Intersect(dq[front + len - 1], dq[front + len - 2]))) --len;
  while (len > 2 && out(dq[front + len - 1], Intersect(dq[front], dq[front + 1]))) {
    ++front;
    --len;
  }
  if (len < 3) return false;
  for (int k = 0; k < len; ++k) {
    const Line& a = dq[front + k];
    const Line& b = dq[front + (k + 1) % len];
    if (Cross(a.u, b.u) <= 0.0) return false;  // consecutive normals must turn left by < pi
    vertices->push_back(Intersect(a, b));
  }
  return true;
}

}  // namespace

HalfPlanes::HalfPlanes(std::span<const double> angle, double bound) : bound_(bound) {
  // The columns' normals, then the bounding box's four (source -1: h = bound).
  std::vector<Eigen::Vector2d> normal;
  normal.reserve(angle.size() + 4);
  for (double a : angle) normal.emplace_back(std::cos(a), std::sin(a));
  for (int q = 0; q < 4; ++q) normal.emplace_back(std::cos(q * M_PI / 2), std::sin(q * M_PI / 2));
  std::vector<double> order_angle(normal.size());
  std::vector<int> order(normal.size());
  for (std::size_t k = 0; k < normal.size(); ++k) {
    order_angle[k] = std::atan2(normal[k].y(), normal[k].x());
    order[k] = static_cast<int>(k);
  }
  // By angle alone, once: the order every intersection of these directions needs.
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return order_angle[a] < order_angle[b]; });
  for (int k : order) {
    normal_.push_back(normal[static_cast<std::size_t>(k)]);
    source_.push_back(k < static_cast<int>(angle.size()) ? k : -1);
  }
}

bool HalfPlanes::Intersect(std::span<const double> h,
                           std::vector<Eigen::Vector2d>* vertices) const {
  std::vector<Line> lines(normal_.size());
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const int j = source_[k];
    lines[k] = {normal_[k], j >= 0 ? h[static_cast<std::size_t>(j)] : bound_};
  }
  return IntersectSorted(lines, bound_, vertices);
}

bool IntersectHalfPlanes(std::span<const double> angle, std::span<const double> h, double bound,
                         std::vector<Eigen::Vector2d>* vertices) {
  return HalfPlanes(angle, bound).Intersect(h, vertices);
}

Eigen::Vector2d ProjectOntoPolygon(const Eigen::Vector2d* v, int count,
                                   const Eigen::Vector2d& x) noexcept {
  if (count == 1) return v[0];
  bool inside = count >= 3;
  double best = std::numeric_limits<double>::infinity();
  double area2 = 0.0, longest2 = 0.0;
  Eigen::Vector2d nearest = v[0];
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d& a = v[k];
    const Eigen::Vector2d& b = v[(k + 1) % count];
    const Eigen::Vector2d e = b - a;
    if (Cross(e, x - a) < 0.0) inside = false;
    area2 += Cross(a - v[0], b - v[0]);
    longest2 = std::max(longest2, e.squaredNorm());
    const double ee = e.squaredNorm();
    const double t = ee > 0.0 ? std::clamp((x - a).dot(e) / ee, 0.0, 1.0) : 0.0;
    const Eigen::Vector2d c = a + t * e;
    const double d = (x - c).squaredNorm();
    if (d < best) {
      best = d;
      nearest = c;
    }
  }
  // A polygon closed down to a point or a segment (coincident vertices, zero-length edges) has
  // no inside to test against: every point's answer is its nearest point.
  if (!(area2 > 1e-12 * longest2) || longest2 == 0.0) inside = false;
  return inside ? x : nearest;
}

double RayExtent(const Eigen::Vector2d* v, int count, const Eigen::Vector2d& direction) noexcept {
  if (count < 3) return 0.0;
  double extent = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d& a = v[k];
    const Eigen::Vector2d e = v[(k + 1) % count] - a;
    const Eigen::Vector2d normal(e.y(), -e.x());  // outward for a CCW polygon
    const double offset = normal.dot(a);          // origin inside <=> offset >= 0 for all edges
    if (normal.squaredNorm() == 0.0) continue;
    if (offset < 0.0) return 0.0;
    const double along = normal.dot(direction);
    if (along > 0.0) extent = std::min(extent, offset / along);
  }
  return std::isfinite(extent) ? extent : 0.0;
}

bool FanAngles(const Eigen::Vector2d* v, int count, const Eigen::Vector2d& centre,
               double* angles) noexcept {
  if (count < 3) return false;
  double area2 = 0.0, longest2 = 0.0;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d e = v[(k + 1) % count] - v[k];
    area2 += Cross(v[k] - v[0], v[(k + 1) % count] - v[0]);
    longest2 = std::max(longest2, e.squaredNorm());
    // Strictly inside: left of every edge that has a length, by more than rounding.
    if (e.squaredNorm() > 0.0 && !(Cross(e, centre - v[k]) > 1e-12 * e.squaredNorm())) {
      return false;
    }
  }
  // As ProjectOntoPolygon: a polygon closed down to a point or a segment has no inside.
  if (!(area2 > 1e-12 * longest2) || longest2 == 0.0) return false;
  const double first = PseudoAngle(v[0] - centre);
  angles[0] = first;
  for (int k = 1; k < count; ++k) {
    double a = PseudoAngle(v[k] - centre);
    while (a < angles[k - 1]) a += kPseudoTurn;
    angles[k] = a;
  }
  return angles[count - 1] < first + kPseudoTurn;
}

namespace {

// The edge k (from vertex k to k + 1) whose wedge about the fan's centre holds pseudo-angle
// `angle`.
int WedgeOf(const double* angles, int count, double angle) noexcept {
  double a = angle - angles[0];  // both in [0, 4)
  if (a < 0.0) a += kPseudoTurn;
  a += angles[0];
  const int k = static_cast<int>(std::upper_bound(angles, angles + count, a) - angles) - 1;
  return std::clamp(k, 0, count - 1);
}

double SegmentDistance2(const Eigen::Vector2d* v, int count, int k, const Eigen::Vector2d& x,
                        Eigen::Vector2d* nearest) noexcept {
  const Eigen::Vector2d& a = v[k];
  const Eigen::Vector2d e = v[(k + 1) % count] - a;
  const double ee = e.squaredNorm();
  const double t = ee > 0.0 ? std::clamp((x - a).dot(e) / ee, 0.0, 1.0) : 0.0;
  *nearest = a + t * e;
  return (x - *nearest).squaredNorm();
}

}  // namespace

Eigen::Vector2d ProjectOntoPolygon(const Eigen::Vector2d* v, int count, const PolygonFan& fan,
                                   const Eigen::Vector2d& x) noexcept {
  if (!fan.valid()) return ProjectOntoPolygon(v, count, x);
  const Eigen::Vector2d r = x - fan.centre;
  const int k = WedgeOf(fan.angles, count, PseudoAngle(r));
  const Eigen::Vector2d e = v[(k + 1) % count] - v[k];
  if (Cross(e, x - v[k]) >= 0.0) return x;  // on the inner side of the edge of its wedge: inside
  Eigen::Vector2d best_point, point;
  double best = SegmentDistance2(v, count, k, x, &best_point);
  // Forwards while the distance falls, else backwards; a full turn bounds the walk.
  // Coincident vertices (edges of no length) are stepped over: their distance is their end's.
  auto walk = [&](int direction) {
    bool moved = false;
    int j = k;
    for (int steps = 1; steps < count; ++steps) {
      j = (j + direction + count) % count;
      if (v[(j + 1) % count] == v[j]) continue;
      const double d = SegmentDistance2(v, count, j, x, &point);
      if (!(d < best)) break;
      best = d;
      best_point = point;
      moved = true;
    }
    return moved;
  };
  if (!walk(+1)) walk(-1);
  return best_point;
}

double RayExtent(const Eigen::Vector2d* v, int count, const PolygonFan& fan,
                 const Eigen::Vector2d& direction) noexcept {
  if (!fan.valid()) return RayExtent(v, count, direction);
  const int k = WedgeOf(fan.angles, count, PseudoAngle(direction));
  const Eigen::Vector2d& a = v[k];
  const Eigen::Vector2d e = v[(k + 1) % count] - a;
  const Eigen::Vector2d normal(e.y(), -e.x());
  const double along = normal.dot(direction);
  if (!(along > 0.0)) return 0.0;
  return normal.dot(a) / along;
}

Eigen::Vector2d PolygonCentroid(const Eigen::Vector2d* v, int count) noexcept {
  Eigen::Vector2d mean(0.0, 0.0);
  for (int k = 0; k < count; ++k) mean += v[k];
  mean /= std::max(count, 1);
  // Shoelace about the vertex mean, so that a micrometre polygon far from the origin keeps its
  // digits.
  double area2 = 0.0, size2 = 0.0;
  Eigen::Vector2d sum(0.0, 0.0);
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d a = v[k] - mean;
    const Eigen::Vector2d b = v[(k + 1) % count] - mean;
    const double c = Cross(a, b);
    area2 += c;
    sum += c * (a + b);
    size2 = std::max(size2, a.squaredNorm());
  }
  // Below this the polygon is a point or a segment (rounding noise in the shoelace sum).
  if (!(std::abs(area2) > 1e-9 * size2)) return mean;
  return mean + sum / (3.0 * area2);
}

}  // namespace fitfeel
