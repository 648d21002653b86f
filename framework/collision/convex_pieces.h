#pragma once

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framework/collision/coarse_mesh.h"
#include "framework/core/export.h"

namespace fitfeel {

// One convex solid of a coarse mesh: its vertices and its distinct face planes (outward unit
// normal n, offset d = n . v of the face's points: the solid's largest projection on n), each
// coordinate apart so that projections run vectorised, and its bounding box.
struct ConvexPiece {
  std::vector<double> x, y, z;
  std::vector<double> nx, ny, nz, offsets;
  // The solid's corners' neighbours along its edges (vertex i's from first_neighbour[i] to
  // first_neighbour[i + 1]; none for a vertex that is no corner, inside a face or an edge, as a
  // cap's centre): a linear function's least over a convex solid is at a corner none of whose
  // neighbours is less, so a walk from a good start finds it in a few steps. `corner`: one of them.
  std::vector<int> first_neighbour, neighbours;
  int corner = 0;
  Eigen::Vector3d low, high;
  int vertex_count() const { return static_cast<int>(x.size()); }
  int plane_count() const { return static_cast<int>(nx.size()); }
};

// The convex solids a mesh is made of: its connected components (triangles sharing a vertex),
// each of which must be convex (no vertex in front of any of its triangles' planes by more than
// 1e-9 of the component's size). nullopt when one is not: such a mesh goes to FCL's hierarchy.
FITFEEL_API std::optional<std::vector<ConvexPiece>> ConvexPieces(const TriangleMesh& mesh);

// The least of u . v over the piece's vertices, walking its corners from *start (a corner; left
// where the walk ended, the next walk's start): the same as a scan of every vertex.
FITFEEL_API double LeastByWalk(const ConvexPiece& piece, const Eigen::Vector3d& u, int* start);

// What a query of two sets of pieces changes, sized once for the pair (no allocation per query).
struct ConvexPiecesScratch {
  // The moving pieces in the scene frame (as ConvexPiece; low / high: their boxes).
  std::vector<ConvexPiece> moving;
  // Per pair of pieces and fixed plane: the moving vertex where the last query's walk ended (its
  // next walk starts there: the part moves little from one tick to the next).
  std::vector<int> walk_start;
  std::size_t walk_stride = 0;  // planes per pair in walk_start: the most of any fixed piece
  std::vector<char> placed;     // per moving piece: its vertices and planes are this query's
  std::vector<std::size_t> first_plane;  // per moving piece: where its planes start in `cosines`
  struct Overlap {
    int moving, fixed;
    std::size_t first_axis;  // its overlap along each face normal, from here in axis_overlaps
    double depth;            // the least of them
    Eigen::Vector3d axis;    // and its direction (the way the moving piece leaves)
  };
  std::vector<Overlap> overlaps;
  std::vector<double> axis_overlaps;
  std::vector<double> least;    // per plane of a moving piece: a fixed piece's least projection
  std::vector<double> cosines;  // per plane of every moving piece: its cosine with an axis tried
  void Reserve(std::span<const ConvexPiece> moving_pieces, std::span<const ConvexPiece> fixed);
};

// The moving pieces (placed by `pose`) against the fixed ones (in the scene frame). Each pair is
// separated, or overlaps by the least of its overlaps along the face normals of both pieces
// (separating-axis test; the edge-edge axes are left out, so a pair crossing edge on edge
// reports more than its true overlap, never less). The moving piece's least projection on each of
// the fixed piece's normals is found by a walk over its corners from where the last query's walk
// ended (the part moves little between ticks), its own normals against the fixed piece's few
// vertices by a vectorised scan. The way out of every overlap at once is
// searched along the pairs' axes summed with their depths and along the deepest pairs' axes (up
// to kDeepestAxesTried distinct): along each, the translation that clears every overlapping pair
// (each pair's exit from its Minkowski difference, bounded by its face normals), and the least of
// these is the answer. Returns the number of overlapping pairs (0: free); with at least one,
// `depth` > 0 is that translation, `normal` its direction (the moving part's way out) and
// `point` the overlapping pairs' box intersections' centre, weighted by their overlaps. No
// allocation once `scratch` is reserved.
int PenetrationOfPieces(std::span<const ConvexPiece> moving, std::span<const ConvexPiece> fixed,
                        const Eigen::Isometry3d& pose, ConvexPiecesScratch* scratch, double* depth,
                        Eigen::Vector3d* normal, Eigen::Vector3d* point) noexcept;

inline constexpr int kDeepestAxesTried = 2;

}  // namespace fitfeel
