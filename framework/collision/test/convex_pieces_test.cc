#include "framework/collision/convex_pieces.h"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// A prism (its caps fans around a centre vertex) and a tube's sectors: every corner of a prism or
// a hexahedron meets three edges; a cap's centre is no corner and has no neighbours to walk to.
TEST(ConvexPiecesTest, CornersAndTheirEdges) {
  const int n = 12;
  const auto prism = ConvexPieces(MakeClosedCylinder(10e-3, -60e-3, 0.0, n));
  ASSERT_TRUE(prism.has_value());
  ASSERT_EQ(prism->size(), 1u);
  const ConvexPiece& p = prism->front();
  EXPECT_EQ(p.plane_count(), n + 2);
  int corners = 0;
  for (int i = 0; i < p.vertex_count(); ++i) {
    const int degree = p.first_neighbour[static_cast<std::size_t>(i) + 1] -
                       p.first_neighbour[static_cast<std::size_t>(i)];
    EXPECT_TRUE(degree == 3 || degree == 0) << i;
    corners += degree == 3 ? 1 : 0;
  }
  EXPECT_EQ(corners, 2 * n);  // the caps' centres are no corners
  const auto tube = ConvexPieces(MakeTube(10e-3, 15e-3, 0.0, 20e-3, n));
  ASSERT_TRUE(tube.has_value());
  ASSERT_EQ(tube->size(), static_cast<std::size_t>(n));
  for (const ConvexPiece& sector : *tube) {
    EXPECT_EQ(sector.plane_count(), 6);
    ASSERT_EQ(sector.vertex_count(), 8);
    for (int i = 0; i < 8; ++i) {
      EXPECT_EQ(sector.first_neighbour[static_cast<std::size_t>(i) + 1] -
                    sector.first_neighbour[static_cast<std::size_t>(i)],
                3);
    }
  }
}

// The walk's least is the scan's, bit for bit, from any corner and in any direction, including
// directions along which whole faces tie (a cap's normal, a facet's): where a walk through the
// caps' centres would stop on the first cap it reached.
TEST(ConvexPiecesTest, AWalkFindsTheLeastFromAnyCorner) {
  std::mt19937 gen(5);
  std::normal_distribution<double> normal;
  for (int n : {8, 50, 200}) {
    TriangleMesh mesh = MakeClosedCylinder(10e-3, -60e-3, -1e-3, n);
    AppendMesh(MakeClosedFrustum(10e-3, 9e-3, -1e-3, 0.0, n), &mesh);
    AppendMesh(MakeTaperedTube(11e-3, 10e-3, 15e-3, -1e-3, 0.0, n), &mesh);
    const auto pieces = ConvexPieces(mesh);
    ASSERT_TRUE(pieces.has_value());
    for (const ConvexPiece& piece : *pieces) {
      std::vector<Eigen::Vector3d> directions = {
          Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX()};
      for (int k = 0; k < piece.plane_count(); ++k) {
        const auto kk = static_cast<std::size_t>(k);
        directions.emplace_back(piece.nx[kk], piece.ny[kk], piece.nz[kk]);
      }
      for (int r = 0; r < 20; ++r) {
        directions.push_back(Eigen::Vector3d(normal(gen), normal(gen), normal(gen)).normalized());
      }
      for (const Eigen::Vector3d& u : directions) {
        double scan = std::numeric_limits<double>::infinity();
        for (int i = 0; i < piece.vertex_count(); ++i) {
          const auto ii = static_cast<std::size_t>(i);
          const double p = u.x() * piece.x[ii] + u.y() * piece.y[ii] + u.z() * piece.z[ii];
          scan = p < scan ? p : scan;
        }
        for (int start = 0; start < piece.vertex_count(); ++start) {
          const auto s = static_cast<std::size_t>(start);
          if (piece.first_neighbour[s + 1] == piece.first_neighbour[s]) continue;  // no corner
          int at = start;
          EXPECT_EQ(LeastByWalk(piece, u, &at), scan) << "n " << n << " from " << start;
        }
      }
    }
  }
}

TEST(ConvexPiecesTest, AMeshWithAPartThatIsNotConvexIsNoPieces) {
  TriangleMesh mesh = MakeClosedCylinder(10e-3, -60e-3, 0.0, 16);
  // A tube as one solid: its bore's walls face the axis, in front of the outer walls' planes.
  TriangleMesh tube = MakeTube(10e-3, 15e-3, 0.0, 20e-3, 16);
  for (Eigen::Vector3i& t : tube.triangles) {
    // Weld every sector into one component by renumbering coincident corners.
    for (int k = 0; k < 3; ++k) {
      for (int j = 0; j < t[k]; ++j) {
        if ((tube.vertices[static_cast<std::size_t>(j)] -
             tube.vertices[static_cast<std::size_t>(t[k])])
                .norm() < 1e-12) {
          t[k] = j;
          break;
        }
      }
    }
  }
  EXPECT_TRUE(ConvexPieces(mesh).has_value());
  EXPECT_FALSE(ConvexPieces(tube).has_value());
}

}  // namespace
}  // namespace fitfeel
