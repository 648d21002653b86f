#include "framework/collision/convex_pieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "framework/core/simd_clones.h"

namespace fitfeel {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

int Root(std::vector<int>* parent, int v) {
  while ((*parent)[static_cast<std::size_t>(v)] != v) {
    int& p = (*parent)[static_cast<std::size_t>(v)];
    p = (*parent)[static_cast<std::size_t>(p)];  // path halving
    v = p;
  }
  return v;
}

// u . (vertex i of the piece).
double Along(const ConvexPiece& piece, std::size_t i, const Eigen::Vector3d& u) {
  return u.x() * piece.x[i] + u.y() * piece.y[i] + u.z() * piece.z[i];
}

Eigen::Vector3d Normal(const ConvexPiece& piece, std::size_t k) {
  return {piece.nx[k], piece.ny[k], piece.nz[k]};
}

// The least over a pair's face normals of overlap(n) / cos(n, u) where the cosine is positive:
// how far along u its Minkowski difference reaches (see PenetrationOfPieces).
template <typename Cosines>
double LeastExit(const double* overlaps, const Cosines& cosine) {
  const Eigen::Map<const Eigen::ArrayXd> overlap(overlaps, cosine.size());
  return (cosine > 1e-12).select(overlap / cosine, kInfinity).minCoeff();
}

// least[k] = min over the n points of n_k . p, for each of the m planes' normals n_k: the points'
// projections on many axes at once, the axes in the inner loop (independent lanes, vectorised;
// compiled also for AVX2 and AVX-512, each lane's sum in the same order: the same numbers).
FITFEEL_SIMD_CLONES void LeastOnPlanes(const double* __restrict nx, const double* __restrict ny,
                                       const double* __restrict nz, int m,
                                       const double* __restrict x, const double* __restrict y,
                                       const double* __restrict z, int n,
                                       double* __restrict least) {
  FITFEEL_NO_FP_CONTRACT
  for (int k = 0; k < m; ++k) least[k] = kInfinity;
  for (int i = 0; i < n; ++i) {
    const double px = x[i], py = y[i], pz = z[i];
    for (int k = 0; k < m; ++k) {
      const double p = nx[k] * px + ny[k] * py + nz[k] * pz;
      least[k] = p < least[k] ? p : least[k];
    }
  }
}

// t[k] = offset_k - least of n_k . p over the points: how far the points' piece must go along
// n_k to leave the planes' piece, for each of its face planes. False (t partly written) as soon as
// one is not positive: a separating plane.
bool OverlapsAlong(const ConvexPiece& planes, const ConvexPiece& points, double* t, double* least) {
  const int m = planes.plane_count();
  if (m >= 16) {
    // Many planes: all of them at once, the planes in the lanes.
    LeastOnPlanes(planes.nx.data(), planes.ny.data(), planes.nz.data(), m, points.x.data(),
                  points.y.data(), points.z.data(), points.vertex_count(), least);
    for (int k = 0; k < m; ++k) {
      t[k] = planes.offsets[static_cast<std::size_t>(k)] - least[k];
      if (!(t[k] > 0.0)) return false;
    }
    return true;
  }
  // Few planes, many points: plane by plane, the points' projections and their least as Eigen's
  // packets (a least is the same whatever order the points are taken in), stopping at the first
  // that separates.
  const auto n = static_cast<Eigen::Index>(points.vertex_count());
  const Eigen::Map<const Eigen::ArrayXd> x(points.x.data(), n), y(points.y.data(), n),
      z(points.z.data(), n);
  for (std::size_t k = 0; k < planes.nx.size(); ++k) {
    t[k] = planes.offsets[k] - (planes.nx[k] * x + planes.ny[k] * y + planes.nz[k] * z).minCoeff();
    if (!(t[k] > 0.0)) return false;
  }
  return true;
}

// As OverlapsAlong for a fixed piece's planes against a placed moving piece, each plane's least
// found by walking the moving piece's vertices from where its last walk ended (`start`, one per
// plane, updated): the same least as a scan of every vertex (a convex solid's), in a few steps.
bool OverlapsAlongByWalks(const ConvexPiece& planes, const ConvexPiece& points, int* start,
                          double* t) {
  for (std::size_t k = 0; k < planes.nx.size(); ++k) {
    t[k] = planes.offsets[k] - LeastByWalk(points, Normal(planes, k), &start[k]);
    if (!(t[k] > 0.0)) return false;
  }
  return true;
}

// The piece's corners (vertices on three of its face planes or more) and their neighbours (two
// corners on two common face planes share the edge where those faces meet): first_neighbour,
// neighbours and corner.
void Connect(ConvexPiece* piece) {
  const double tolerance = 1e-9 * (piece->high - piece->low).norm();
  const int count = piece->vertex_count();
  std::vector<std::vector<int>> on(static_cast<std::size_t>(count));  // each vertex's planes
  for (int i = 0; i < count; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    for (std::size_t k = 0; k < piece->nx.size(); ++k) {
      const double p = Along(*piece, ii, Normal(*piece, k));
      if (std::abs(p - piece->offsets[k]) <= tolerance) on[ii].push_back(static_cast<int>(k));
    }
  }
  // Corners on the same two planes, grouped by that pair of planes (each corner lies on three or
  // more, so on three pairs or more): the two ends of an edge.
  std::vector<std::array<int, 3>> on_pairs;  // (plane, plane, corner)
  piece->corner = -1;
  for (int i = 0; i < count; ++i) {
    const std::vector<int>& planes = on[static_cast<std::size_t>(i)];
    if (planes.size() < 3) continue;
    if (piece->corner < 0) piece->corner = i;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      for (std::size_t q = p + 1; q < planes.size(); ++q)
        on_pairs.push_back({planes[p], planes[q], i});
    }
  }
  std::sort(on_pairs.begin(), on_pairs.end());
  std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(count));
  for (std::size_t g = 0; g < on_pairs.size();) {
    std::size_t end = g;
    while (end < on_pairs.size() && on_pairs[end][0] == on_pairs[g][0] &&
           on_pairs[end][1] == on_pairs[g][1]) {
      ++end;
    }
    for (std::size_t a = g; a < end; ++a) {
      for (std::size_t b = g; b < end; ++b) {
        if (a != b) adjacent[static_cast<std::size_t>(on_pairs[a][2])].push_back(on_pairs[b][2]);
      }
    }
    g = end;
  }
  piece->first_neighbour.assign(1, 0);
  piece->neighbours.clear();
  for (std::vector<int>& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    piece->neighbours.insert(piece->neighbours.end(), list.begin(), list.end());
    piece->first_neighbour.push_back(static_cast<int>(piece->neighbours.size()));
  }
}

// The least of u . v over a piece's vertices.
double LeastProjection(const ConvexPiece& piece, const Eigen::Vector3d& u) {
  double least = kInfinity;
  for (std::size_t i = 0; i < piece.x.size(); ++i) {
    const double p = Along(piece, i, u);
    least = p < least ? p : least;
  }
  return least;
}

// `piece` placed by the rotation and translation into `out` (sized as it), with its exact box.
void Place(const ConvexPiece& piece, const Eigen::Matrix3d& rotation,
           const Eigen::Vector3d& translation, ConvexPiece* out) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(kInfinity), high = -low;
  for (std::size_t i = 0; i < piece.x.size(); ++i) {
    const Eigen::Vector3d p =
        rotation * Eigen::Vector3d(piece.x[i], piece.y[i], piece.z[i]) + translation;
    out->x[i] = p.x();
    out->y[i] = p.y();
    out->z[i] = p.z();
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  out->low = low;
  out->high = high;
  for (std::size_t k = 0; k < piece.nx.size(); ++k) {
    const Eigen::Vector3d n = rotation * Eigen::Vector3d(piece.nx[k], piece.ny[k], piece.nz[k]);
    out->nx[k] = n.x();
    out->ny[k] = n.y();
    out->nz[k] = n.z();
    out->offsets[k] = piece.offsets[k] + n.dot(translation);
  }
}

bool BoxesApart(const ConvexPiece& a, const ConvexPiece& b) {
  return (a.low.array() >= b.high.array()).any() || (b.low.array() >= a.high.array()).any();
}

}  // namespace

double LeastByWalk(const ConvexPiece& piece, const Eigen::Vector3d& u, int* start) {
  auto along = [&](int v) { return Along(piece, static_cast<std::size_t>(v), u); };
  int at = *start;
  double least = along(at);
  for (bool moved = true; moved;) {
    moved = false;
    const int end = piece.first_neighbour[static_cast<std::size_t>(at) + 1];
    for (int e = piece.first_neighbour[static_cast<std::size_t>(at)]; e < end; ++e) {
      const int next = piece.neighbours[static_cast<std::size_t>(e)];
      const double p = along(next);
      if (p < least) {
        least = p;
        at = next;
        moved = true;
      }
    }
  }
  *start = at;
  return least;
}

std::optional<std::vector<ConvexPiece>> ConvexPieces(const TriangleMesh& mesh) {
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 1; k < 3; ++k) {
      const int a = Root(&parent, t[0]), b = Root(&parent, t[k]);
      parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  }
  // Components in the order of their least vertex, vertices and triangles in mesh order.
  std::vector<int> component(static_cast<std::size_t>(n), -1), triangle_component;
  std::vector<std::vector<int>> vertices;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const int root = Root(&parent, t[0]);
    if (component[static_cast<std::size_t>(root)] < 0) {
      component[static_cast<std::size_t>(root)] = static_cast<int>(vertices.size());
      vertices.emplace_back();
    }
    triangle_component.push_back(component[static_cast<std::size_t>(root)]);
  }
  for (int v = 0; v < n; ++v) {
    const int c = component[static_cast<std::size_t>(Root(&parent, v))];
    if (c >= 0) vertices[static_cast<std::size_t>(c)].push_back(v);
  }
  std::vector<ConvexPiece> pieces(vertices.size());
  for (std::size_t c = 0; c < pieces.size(); ++c) {
    ConvexPiece& piece = pieces[c];
    piece.low = Eigen::Vector3d::Constant(kInfinity);
    piece.high = -piece.low;
    for (int v : vertices[c]) {
      const Eigen::Vector3d& p = mesh.vertices[static_cast<std::size_t>(v)];
      piece.x.push_back(p.x());
      piece.y.push_back(p.y());
      piece.z.push_back(p.z());
      piece.low = piece.low.cwiseMin(p);
      piece.high = piece.high.cwiseMax(p);
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    ConvexPiece& piece = pieces[static_cast<std::size_t>(triangle_component[t])];
    const double size = (piece.high - piece.low).norm();
    const double tolerance = 1e-9 * size;
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t>(tri[0])];
    const Eigen::Vector3d cross = (mesh.vertices[static_cast<std::size_t>(tri[1])] - a)
                                      .cross(mesh.vertices[static_cast<std::size_t>(tri[2])] - a);
    // A sliver (collinear corners) has no plane of its own; its edges lie on its neighbours'.
    if (!(cross.norm() > 1e-12 * size * size)) continue;
    const Eigen::Vector3d normal = cross.normalized();
    const double offset = normal.dot(a);
    bool known = false;
    for (std::size_t k = 0; k < piece.nx.size() && !known; ++k) {
      known = Eigen::Vector3d(piece.nx[k], piece.ny[k], piece.nz[k]).dot(normal) >= 1.0 - 1e-12 &&
              std::abs(piece.offsets[k] - offset) <= tolerance;
    }
    if (known) continue;
    const double greatest = -LeastProjection(piece, -normal);
    if (greatest - offset > tolerance) return std::nullopt;  // a vertex in front: not convex
    piece.nx.push_back(normal.x());
    piece.ny.push_back(normal.y());
    piece.nz.push_back(normal.z());
    piece.offsets.push_back(greatest);
  }
  for (const ConvexPiece& piece : pieces) {
    if (piece.plane_count() < 4) return std::nullopt;  // flat: no solid
  }
  for (ConvexPiece& piece : pieces) {
    Connect(&piece);
    if (piece.corner < 0) return std::nullopt;  // no corner found to rounding: leave it to FCL
  }
  return pieces;
}

void ConvexPiecesScratch::Reserve(std::span<const ConvexPiece> moving_pieces,
                                  std::span<const ConvexPiece> fixed) {
  moving.assign(moving_pieces.begin(), moving_pieces.end());
  placed.assign(moving.size(), 0);
  walk_stride = 0;
  for (const ConvexPiece& b : fixed) walk_stride = std::max(walk_stride, b.nx.size());
  walk_start.clear();
  first_plane.clear();
  std::size_t axes = 0, planes = 0, most = 0;
  for (const ConvexPiece& a : moving) {
    walk_start.insert(walk_start.end(), fixed.size() * walk_stride, a.corner);
    first_plane.push_back(planes);
    planes += a.nx.size();
    most = std::max(most, a.nx.size());
    for (const ConvexPiece& b : fixed) axes += a.nx.size() + b.nx.size();
  }
  overlaps.clear();
  overlaps.reserve(moving.size() * fixed.size());
  axis_overlaps.resize(axes);
  least.resize(most);
  cosines.resize(planes);
}

int PenetrationOfPieces(std::span<const ConvexPiece> moving, std::span<const ConvexPiece> fixed,
                        const Eigen::Isometry3d& pose, ConvexPiecesScratch* scratch, double* depth,
                        Eigen::Vector3d* normal, Eigen::Vector3d* point) noexcept {
  ConvexPiecesScratch& s = *scratch;
  const Eigen::Matrix3d rotation = pose.linear();
  const Eigen::Vector3d translation = pose.translation();
  // Each moving piece's box in the scene frame, first from its own box's corners (a bound); the
  // piece is placed vertex by vertex only once a fixed piece's box meets that.
  for (std::size_t a = 0; a < moving.size(); ++a) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(kInfinity), high = -low;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d local((corner & 1) ? moving[a].high.x() : moving[a].low.x(),
                                  (corner & 2) ? moving[a].high.y() : moving[a].low.y(),
                                  (corner & 4) ? moving[a].high.z() : moving[a].low.z());
      const Eigen::Vector3d p = rotation * local + translation;
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    s.moving[a].low = low;
    s.moving[a].high = high;
    s.placed[a] = 0;
  }
  // Every pair whose boxes meet, by separating axes: along each of the pair's face normals (the
  // fixed piece's, then the moving piece's reversed), how far the moving piece must go to leave
  // the fixed one (<= 0: they are apart).
  s.overlaps.clear();
  std::size_t cursor = 0;
  for (std::size_t a = 0; a < moving.size(); ++a) {
    ConvexPiece& m = s.moving[a];
    for (std::size_t b = 0; b < fixed.size(); ++b) {
      const ConvexPiece& f = fixed[b];
      if (BoxesApart(m, f)) continue;
      if (!s.placed[a]) {
        Place(moving[a], rotation, translation, &m);
        s.placed[a] = 1;
        if (BoxesApart(m, f)) continue;
      }
      ConvexPiecesScratch::Overlap o{static_cast<int>(a), static_cast<int>(b), cursor, kInfinity,
                                     Eigen::Vector3d::Zero()};
      double* t = s.axis_overlaps.data() + cursor;
      int* start = s.walk_start.data() + (a * fixed.size() + b) * s.walk_stride;
      if (!OverlapsAlongByWalks(f, m, start, t) ||
          !OverlapsAlong(m, f, t + f.nx.size(), s.least.data())) {
        continue;
      }
      const std::size_t axes = f.nx.size() + m.nx.size();
      for (std::size_t k = 0; k < axes; ++k) {
        if (t[k] < o.depth) {
          o.depth = t[k];
          o.axis = k < f.nx.size() ? Normal(f, k) : Eigen::Vector3d(-Normal(m, k - f.nx.size()));
        }
      }
      s.overlaps.push_back(o);
      cursor += f.nx.size() + m.nx.size();
    }
  }
  const int overlapping = static_cast<int>(s.overlaps.size());
  if (overlapping == 0) return 0;
  // The way out of every overlap at once, tried along the pairs' axes summed with their depths
  // (a part pressed into a faceted bore overlaps the facets around its offset's direction, and
  // no one facet's normal is that direction), then along the deepest pairs' own axes. Along a
  // unit vector u a pair is left once the ray t u leaves its Minkowski difference (convex,
  // holding the origin) through one of its faces; each face normal n bounds that exit,
  // t <= overlap(n) / (n . u) where n . u > 0, and the least of these bounds over the pair's face
  // normals is never short of it (edge-edge normals left out). The largest over the pairs clears
  // them all.
  std::array<Eigen::Vector3d, kDeepestAxesTried + 1> tried;
  int candidates = 0;
  double best = kInfinity;
  Eigen::Vector3d best_axis = Eigen::Vector3d::Zero();
  auto try_axis = [&](const Eigen::Vector3d& u) {
    tried[static_cast<std::size_t>(candidates++)] = u;
    // The moving pieces' reversed normals' cosines with u, once for all their pairs.
    for (std::size_t a = 0; a < moving.size(); ++a) {
      const ConvexPiece& m = s.moving[a];
      if (!s.placed[a]) continue;
      for (std::size_t k = 0; k < m.nx.size(); ++k) {
        s.cosines[s.first_plane[a] + k] = -(m.nx[k] * u.x() + m.ny[k] * u.y() + m.nz[k] * u.z());
      }
    }
    double required = 0.0;
    for (const ConvexPiecesScratch::Overlap& o : s.overlaps) {
      const ConvexPiece& f = fixed[static_cast<std::size_t>(o.fixed)];
      const double* t = s.axis_overlaps.data() + o.first_axis;
      const auto fixed_planes = static_cast<Eigen::Index>(f.nx.size());
      const Eigen::Map<const Eigen::ArrayXd> fx(f.nx.data(), fixed_planes),
          fy(f.ny.data(), fixed_planes), fz(f.nz.data(), fixed_planes);
      const auto a = static_cast<std::size_t>(o.moving);
      const Eigen::Map<const Eigen::ArrayXd> moving_cosines(
          s.cosines.data() + s.first_plane[a], static_cast<Eigen::Index>(s.moving[a].nx.size()));
      const double exit = std::min(LeastExit(t, fx * u.x() + fy * u.y() + fz * u.z()),
                                   LeastExit(t + f.nx.size(), moving_cosines));
      required = std::max(required, exit);
    }
    if (required < best) {
      best = required;
      best_axis = u;
    }
  };
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const ConvexPiecesScratch::Overlap& o : s.overlaps) sum += o.depth * o.axis;
  if (sum.norm() > 0.0) try_axis(sum.normalized());
  while (candidates < kDeepestAxesTried + 1) {
    const ConvexPiecesScratch::Overlap* next = nullptr;
    for (const ConvexPiecesScratch::Overlap& o : s.overlaps) {
      bool seen = false;
      for (int c = 0; c < candidates && !seen; ++c) {
        seen = tried[static_cast<std::size_t>(c)].dot(o.axis) >= 1.0 - 1e-12;
      }
      if (!seen && (next == nullptr || o.depth > next->depth)) next = &o;
    }
    if (next == nullptr) break;
    try_axis(next->axis);
  }
  *depth = best;
  *normal = best_axis;
  // Where the force acts: the overlapping pairs' box intersections' centres, each weighted by
  // its pair's overlap.
  Eigen::Vector3d centre_sum = Eigen::Vector3d::Zero();
  double weight = 0.0;
  for (const ConvexPiecesScratch::Overlap& o : s.overlaps) {
    const ConvexPiece& f = fixed[static_cast<std::size_t>(o.fixed)];
    const ConvexPiece& m = s.moving[static_cast<std::size_t>(o.moving)];
    centre_sum += o.depth * 0.5 * (m.low.cwiseMax(f.low) + m.high.cwiseMin(f.high));
    weight += o.depth;
  }
  *point = centre_sum / weight;
  return overlapping;
}

}  // namespace fitfeel
