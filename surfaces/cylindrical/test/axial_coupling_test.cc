#include "surfaces/cylindrical/elastic/axial_coupling.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "framework/core/error.h"
#include "surfaces/cylindrical/elastic/harmonic_compliance.h"

namespace fitfeel::cylindrical {
namespace {

constexpr double kE = 210e9, kNu = 0.3;

AxialBody Shaft(double radius, bool held = false) {
  AxialBody b;
  b.inner_radius = 0.0;
  b.outer_radius = radius;
  b.loaded_inside = false;
  b.material = {"steel", kE, kNu};
  b.held_faces = held;
  return b;
}

AxialBody Hub(double bore, double outside, bool held = false) {
  AxialBody b = Shaft(outside, held);
  b.inner_radius = bore;
  b.loaded_inside = true;
  return b;
}

std::vector<double> Edges(int rows, double pitch) {
  std::vector<double> e(static_cast<std::size_t>(rows) + 1);
  for (int i = 0; i <= rows; ++i) e[static_cast<std::size_t>(i)] = i * pitch;
  return e;
}

// A uniform pressure on the whole length is the Lame state, which the bilinear elements hold
// exactly in a solid shaft (u_r linear in r, u_z in z): u = p a (1 - nu) / E with free faces,
// p a (1 + nu)(1 - 2 nu) / E with held ones (plane strain).
TEST(AxialCoupling, AUniformlyPressedSolidShaftIsLames) {
  const double a = 0.010;
  const AxialCoupling free_faces(Shaft(a), Edges(40, 1e-3));
  const AxialCoupling held(Shaft(a, true), Edges(40, 1e-3));
  const Eigen::VectorXd u = free_faces.influence().rowwise().sum();
  const Eigen::VectorXd v = held.influence().rowwise().sum();
  for (int i = 0; i < 40; ++i) {
    EXPECT_NEAR(u[i], a * (1 - kNu) / kE, 1e-9 * a / kE) << i;
    EXPECT_NEAR(v[i], a * (1 + kNu) * (1 - 2 * kNu) / kE, 1e-9 * a / kE) << i;
  }
}

// The hub's bore under a uniform pressure: Lame's thick cylinder (u = A r + B / r, which the
// elements approximate: 0.25 % low at the free faces, less inside), u(a) = p a / E ((b^2 + a^2) /
// (b^2 - a^2) + nu) with free faces and p a (1 + nu) ((1 - 2 nu) a^2 + b^2) / (E (b^2 - a^2)) with
// held ones.
TEST(AxialCoupling, AUniformlyPressedHubIsLames) {
  const double a = 0.010, b = 0.015;
  const AxialCoupling free_faces(Hub(a, b), Edges(40, 0.5e-3));
  const AxialCoupling held(Hub(a, b, true), Edges(40, 0.5e-3));
  const double plane_stress = a / kE * ((b * b + a * a) / (b * b - a * a) + kNu);
  const double plane_strain =
      a * (1 + kNu) * ((1 - 2 * kNu) * a * a + b * b) / (kE * (b * b - a * a));
  for (int i = 0; i < 40; ++i) {
    EXPECT_NEAR(free_faces.influence().row(i).sum(), plane_stress, 3e-3 * plane_stress) << i;
    EXPECT_NEAR(held.influence().row(i).sum(), plane_strain, 1e-3 * plane_strain) << i;
  }
}

// Maxwell-Betti: on equal rows F is symmetric; on unequal ones F diag(1 / length) is. The extra
// displacement X takes nothing from a uniform load and gives none back (X 1 = 0). With free faces
// it is negative semidefinite: the part is never softer than its plane-stress sections. Held
// faces are not that: plane strain holds every section (a kinematic constraint, not a statically
// admissible stress field), and a band load's section expands axially into its unloaded
// neighbours, so some loads find the part softer (X's largest eigenvalue about +9 % of the
// sections' compliance here).
TEST(AxialCoupling, IsReciprocalAndNeverSofterThanPlaneSections) {
  std::vector<double> uneven{0.0};
  for (int i = 0; i < 30; ++i) uneven.push_back(uneven.back() + (i % 3 == 0 ? 0.8e-3 : 0.5e-3));
  for (const AxialBody& body :
       {Shaft(0.010), Hub(0.010, 0.015), Hub(0.010, 0.012, true), Shaft(0.010, true)}) {
    for (const std::vector<double>& edges : {Edges(40, 0.5e-3), uneven}) {
      const AxialCoupling c(body, edges);
      const auto m = static_cast<Eigen::Index>(edges.size() - 1);
      Eigen::VectorXd length(m);
      for (Eigen::Index i = 0; i < m; ++i) length[i] = edges[i + 1] - edges[i];
      const Eigen::MatrixXd f = c.influence() * length.cwiseInverse().asDiagonal();
      const double scale = c.influence().cwiseAbs().maxCoeff();
      EXPECT_LT((f - f.transpose()).cwiseAbs().maxCoeff(), 1e-9 * f.cwiseAbs().maxCoeff());
      EXPECT_LT((c.matrix() * Eigen::VectorXd::Ones(m)).cwiseAbs().maxCoeff(), 1e-12 * scale);
      // X diag(1 / length) is symmetric too; its eigenvalues, scaled back to a row's pitch.
      const Eigen::MatrixXd x = c.matrix() * length.cwiseInverse().asDiagonal();
      const Eigen::VectorXd eig =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (x + x.transpose())).eigenvalues();
      EXPECT_LT(eig.minCoeff(), -0.1 * scale / length.maxCoeff() * length.minCoeff());
      if (body.held_faces) {
        EXPECT_GT(eig.maxCoeff() * length.maxCoeff(), 0.01 * scale);
      } else {
        EXPECT_LT(eig.maxCoeff() * length.maxCoeff(), 1e-6 * scale);
      }
    }
  }
}

// A thin tube (t / R = 0.05) loaded on half of its length is Hetenyi's beam on an elastic
// foundation (Timoshenko and Woinowsky-Krieger, Theory of Plates and Shells, section 114): away
// from its ends the displacement beyond the load's edge is w0 / 2 e^(-beta x) cos(beta x) and
// w0 (1 - e^(-beta x) cos(beta x) / 2) under the load, beta^4 = 3 (1 - nu^2) / (R t)^2.
TEST(AxialCoupling, AHalfLoadedThinTubeIsHetenyisBeam) {
  const double a = 0.020, t = 0.001, pitch = 0.25e-3;
  const int rows = 240;  // 60 mm: 17 decay lengths
  const AxialCoupling c(Hub(a, a + t), Edges(rows, pitch));
  const double radius = a + 0.5 * t;
  const double beta = std::pow(3 * (1 - kNu * kNu) / (radius * radius * t * t), 0.25);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(rows);
  p.head(rows / 2).setConstant(1.0);
  const Eigen::VectorXd w = c.influence() * p;
  const double w0 = c.influence().row(rows / 4).sum();  // the uniform state's
  int checked = 0;
  for (int i = rows / 2 - 40; i < rows / 2 + 40; ++i) {
    const double x = (i + 0.5) * pitch - 0.5 * rows * pitch;  // from the load's edge
    const double tail = 0.5 * w0 * std::exp(-beta * std::abs(x)) * std::cos(beta * std::abs(x));
    const double expected = x > 0.0 ? tail : w0 - tail;
    EXPECT_NEAR(w[i], expected, 0.03 * w0) << "x = " << x;
    ++checked;
  }
  EXPECT_EQ(checked, 80);
}

// The elements converge: a part's influence on rows of 1 mm (the shaft of the shipped 20 mm
// scenes), and the same rows' influence read from a model on rows of 0.125 mm (a coarse row's load
// on all eight of its parts, its displacement the mean of theirs), agree to 1 % of the largest
// entry for F and 0.7 % for X, the part the sections use (measured 0.89 and 0.62 % for the
// shaft, 0.40 and 0.14 % for the hub; with two elements per row instead of one per 0.25 mm,
// 2.9 and 2.0 % for the shaft).
TEST(AxialCoupling, ConvergesUnderRefinement) {
  for (const AxialBody& body : {Shaft(0.010), Hub(0.010, 0.015)}) {
    const AxialCoupling coarse(body, Edges(20, 1e-3));
    const AxialCoupling fine(body, Edges(160, 0.125e-3));
    Eigen::MatrixXd pool = Eigen::MatrixXd::Zero(20, 160);  // fine rows to coarse ones: the mean
    for (int i = 0; i < 20; ++i) pool.block(i, 8 * i, 1, 8).setConstant(1.0 / 8);
    const Eigen::MatrixXd f = pool * fine.influence() * pool.transpose() * 8.0;
    const Eigen::MatrixXd x = pool * fine.matrix() * pool.transpose() * 8.0;
    EXPECT_LT((f - coarse.influence()).cwiseAbs().maxCoeff(),
              0.01 * coarse.influence().cwiseAbs().maxCoeff())
        << body.loaded_inside;
    EXPECT_LT((x - coarse.matrix()).cwiseAbs().maxCoeff(),
              0.007 * coarse.matrix().cwiseAbs().maxCoeff())
        << body.loaded_inside;
  }
}

// The properties above on parts drawn at random (radii, walls, materials' Poisson ratios, row
// counts and unequal rows): reciprocity, X 1 = 0, and X negative semidefinite with free faces.
TEST(AxialCoupling, HoldsItsPropertiesOnRandomParts) {
  std::mt19937_64 rng(2711);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 24; ++trial) {
    const double radius = 0.003 + 0.03 * unit(rng);
    AxialBody body = unit(rng) < 0.5 ? Shaft(radius) : Hub(radius, radius * (1.1 + unit(rng)));
    if (!body.loaded_inside && unit(rng) < 0.3) body.inner_radius = radius * 0.6 * unit(rng);
    body.material.poisson = 0.1 + 0.35 * unit(rng);
    const int rows = 4 + static_cast<int>(unit(rng) * 30);
    std::vector<double> edges{0.0};
    for (int i = 0; i < rows; ++i)
      edges.push_back(edges.back() + radius * (0.02 + 0.2 * unit(rng)));
    const AxialCoupling c(body, edges);
    Eigen::VectorXd length(rows);
    for (int i = 0; i < rows; ++i) length[i] = edges[i + 1] - edges[i];
    const Eigen::MatrixXd f = c.influence() * length.cwiseInverse().asDiagonal();
    const double scale = c.influence().cwiseAbs().maxCoeff();
    EXPECT_LT((f - f.transpose()).cwiseAbs().maxCoeff(), 1e-8 * f.cwiseAbs().maxCoeff()) << trial;
    EXPECT_LT((c.matrix() * Eigen::VectorXd::Ones(rows)).cwiseAbs().maxCoeff(), 1e-12 * scale)
        << trial;
    const Eigen::MatrixXd x = c.matrix() * length.cwiseInverse().asDiagonal();
    const Eigen::VectorXd eig =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (x + x.transpose())).eigenvalues();
    EXPECT_LT(eig.maxCoeff() * length.maxCoeff(), 1e-6 * scale) << trial;
    EXPECT_TRUE(c.influence().allFinite()) << trial;
  }
}

// Held faces and a uniform load cos(n theta) on every row: plane strain is then the exact 3-D
// state, so each part's rows move by its plane-strain section compliance (Michell for n >= 2,
// the body-force-balanced section about its centroid for n = 1), up to the elements' own
// stiffness (measured: +0.2 % for n = 1, -0.5 to -1.0 % for n = 2 to 10). With free faces the
// middle of this 20 mm part is stiffer than plane stress (n >= 2: the 3-D state lies between
// plane stress and plane strain) and its ends softer; what the model adds to its plane-stress
// sections there is X 1 = F 1 - c_n.
TEST(AxialCoupling, EveryOrderWithHeldFacesIsItsPlaneStrainSection) {
  const std::vector<double> edges = Edges(40, 0.5e-3);
  const Material steel{"steel", kE, kNu};
  for (int n : {1, 2, 3, 5, 10}) {
    for (const AxialBody& body : {Shaft(0.010, true), Hub(0.010, 0.015, true)}) {
      const AxialCoupling part(body, edges, n);
      EXPECT_EQ(part.order(), n);
      const double plane_strain = RingHarmonicCompliance(body.inner_radius, body.outer_radius,
                                                         body.loaded_inside, steel, true, n);
      for (int i : {0, 20, 39}) {
        EXPECT_NEAR(part.influence().row(i).sum(), plane_strain, 0.015 * plane_strain)
            << "order " << n << (body.loaded_inside ? " hub" : " shaft") << " row " << i;
      }
    }
    // Free faces, orders >= 2: stiffer than plane stress in the middle, softer at the ends.
    if (n < 2) continue;
    const AxialBody hub = Hub(0.010, 0.015);
    const AxialCoupling part(hub, edges, n);
    const double plane_stress =
        RingHarmonicCompliance(0.010, 0.015, true, steel, /*plane_strain=*/false, n);
    EXPECT_LT(part.influence().row(20).sum(), 0.97 * plane_stress) << n;
    EXPECT_GT(part.influence().row(0).sum(), part.influence().row(20).sum()) << n;
    EXPECT_NEAR(part.matrix().row(20).sum(), part.influence().row(20).sum() - plane_stress,
                1e-9 * plane_stress);
  }
}

// Maxwell-Betti for every order >= 2 (no rigid motion to take out): F diag(1 / length) is
// symmetric on uneven rows. A load's reach along the axis shrinks with the order (about R / n):
// the displacement 3 mm from a loaded row, relative to the loaded row's own, falls with n.
TEST(AxialCoupling, HigherOrdersAreReciprocalAndReachLess) {
  std::vector<double> uneven{0.0};
  for (int i = 0; i < 24; ++i) uneven.push_back(uneven.back() + (i % 3 == 0 ? 0.8e-3 : 0.5e-3));
  for (int n : {2, 4, 8}) {
    const AxialCoupling part(Hub(0.010, 0.015), uneven, n);
    Eigen::MatrixXd scaled = part.influence();
    for (int j = 0; j < scaled.cols(); ++j) scaled.col(j) /= uneven[j + 1] - uneven[j];
    EXPECT_LT((scaled - scaled.transpose()).norm(), 1e-6 * scaled.norm()) << n;
  }
  const std::vector<double> edges = Edges(40, 0.5e-3);
  double last = 1.0;
  for (int n : {2, 3, 5, 8, 12}) {
    const AxialCoupling part(Shaft(0.010), edges, n);
    const double reach = part.influence()(26, 20) / part.influence()(20, 20);
    EXPECT_LT(reach, last) << n;
    last = reach;
  }
  EXPECT_LT(last, 0.05);
}

// Order 1 carries a net force, which the model's rigid parts take; what the coupling adds is the
// part's bending about its axis. Three bands balanced along a free shaft (no net force or
// moment): the pressed bands open, the pulled one closes, symmetrically about the middle.
TEST(AxialCoupling, OrderOneIsTheDeformationAboutTheAxis) {
  const std::vector<double> edges = Edges(40, 0.5e-3);
  const AxialCoupling free_faces(Shaft(0.010), edges, 1);
  // Rows 5-9 pushed one way, rows 15-24 the other way at half the pressure, rows 30-34 the first
  // way: forces 5 - 5 = 0 per unit pressure and moments about the middle balanced by symmetry.
  Eigen::VectorXd load = Eigen::VectorXd::Zero(40);
  for (int i = 5; i < 10; ++i) load[i] = 1.0;
  for (int i = 15; i < 25; ++i) load[i] = -1.0;
  for (int i = 30; i < 35; ++i) load[i] = 1.0;
  const Eigen::VectorXd u = free_faces.influence() * load;
  // The loaded bands open where pressed (the part bends away from them) and the result is
  // symmetric about the middle.
  EXPECT_GT(u[7], 0.0);
  EXPECT_LT(u[20], 0.0);
  for (int i = 0; i < 20; ++i) EXPECT_NEAR(u[i], u[39 - i], 1e-6 * std::abs(u[7])) << i;
  EXPECT_THROW(AxialCoupling(Shaft(0.010), edges, AxialCoupling::kHighestOrder + 1), UserError);
}

// Order 1 too is reciprocal (Maxwell-Betti: F diag(1 / length) symmetric) once the part's rigid
// motion is taken out as the axis moves: exactly with held faces, to the body loads' balance
// with free ones. A shaft's face opens where its axis moves away from it: the axis's line taken
// out with the hub's sign instead left the shaft's F 35 % (free faces) and 116 % (held)
// unsymmetric, and dependent on where the part was held.
TEST(AxialCoupling, OrderOneIsReciprocalForShaftAndHub) {
  std::vector<double> uneven{0.0};
  for (int i = 0; i < 24; ++i) uneven.push_back(uneven.back() + (i % 3 == 0 ? 0.8e-3 : 0.5e-3));
  for (bool held : {false, true}) {
    for (const AxialBody& body : {Shaft(0.010, held), Hub(0.010, 0.015, held)}) {
      const AxialCoupling part(body, uneven, 1);
      Eigen::MatrixXd scaled = part.influence();
      for (int j = 0; j < scaled.cols(); ++j) scaled.col(j) /= uneven[j + 1] - uneven[j];
      EXPECT_LT((scaled - scaled.transpose()).norm(), (held ? 1e-9 : 1e-3) * scaled.norm())
          << (body.loaded_inside ? "hub" : "shaft") << (held ? ", held faces" : ", free faces");
    }
  }
}

// Rows that mirror about the part's middle solve the far half's loads and mirror the rest: the
// same F as every row solved (rows made unequal by a part in 1e-9, which the mirror test refuses
// and which moves F by about as little), for every kind of part and support.
TEST(AxialCoupling, MirroredRowsGiveWhatSolvingEveryRowGives) {
  std::vector<double> mirrored{0.0};
  for (double step : {0.8e-3, 0.5e-3, 0.5e-3, 0.3e-3, 0.5e-3, 0.5e-3, 0.8e-3}) {
    mirrored.push_back(mirrored.back() + step);
  }
  for (const std::vector<double>& edges : {Edges(14, 0.6e-3), mirrored}) {
    std::vector<double> broken = edges;
    broken[1] *= 1.0 + 1e-9;
    for (int n : {0, 1, 2, 5}) {
      for (bool held : {false, true}) {
        for (const AxialBody& body : {Shaft(0.010, held), Hub(0.010, 0.015, held)}) {
          const Eigen::MatrixXd a = AxialCoupling(body, edges, n).influence();
          const Eigen::MatrixXd b = AxialCoupling(body, broken, n).influence();
          EXPECT_LT((a - b).norm(), 1e-6 * a.norm())
              << "order " << n << (body.loaded_inside ? " hub" : " shaft") << " held " << held
              << " rows " << edges.size() - 1;
        }
      }
    }
  }
}

// The condensed elimination (equal groups of rows eliminated inside once, then the lines between
// them) is the same K^-1 as the whole band: the same F to rounding for every kind of part and
// support, order and grouping (one group, a group per row, several), mirrored or not.
TEST(AxialCoupling, TheCondensedEliminationIsTheBands) {
  using Elimination = AxialCoupling::Elimination;
  for (int rows : {1, 4, 6, 9, 12}) {
    for (double pitch : {0.6e-3, 2.0e-3}) {  // two and eight elements per row on a 10 mm face
      for (int n : {0, 1, 2, 5}) {
        for (bool held : {false, true}) {
          for (const AxialBody& body : {Shaft(0.010, held), Hub(0.010, 0.015, held)}) {
            const std::vector<double> edges = Edges(rows, pitch);
            const Eigen::MatrixXd band =
                AxialCoupling(body, edges, n, Elimination::kBand).influence();
            const Eigen::MatrixXd condensed =
                AxialCoupling(body, edges, n, Elimination::kCondensed).influence();
            EXPECT_LT((band - condensed).cwiseAbs().maxCoeff(), 1e-9 * band.cwiseAbs().maxCoeff())
                << "order " << n << (body.loaded_inside ? " hub" : " shaft") << " held " << held
                << " rows " << rows << " pitch " << pitch;
          }
        }
      }
    }
  }
  // Rows of two lengths have no equal groups: refused when asked for, the band otherwise.
  std::vector<double> uneven = Edges(6, 1e-3);
  uneven[3] += 0.2e-3;
  EXPECT_THROW(AxialCoupling(Shaft(0.010), uneven, 2, Elimination::kCondensed), UserError);
  EXPECT_EQ(AxialCoupling(Shaft(0.010), uneven, 2).influence(),
            AxialCoupling(Shaft(0.010), uneven, 2, Elimination::kBand).influence());
}

// A part's elements are solved anew for each prepared scene: the same arguments give the same
// matrices bit for bit, whatever was solved before.
TEST(AxialCoupling, SolvingAgainGivesTheSameBitForBit) {
  const std::vector<double> edges = Edges(12, 1e-3);
  for (int n : {0, 1, 3}) {
    const AxialCoupling first(Hub(0.010, 0.015), edges, n);
    const AxialCoupling other(Shaft(0.010), edges, n);
    const AxialCoupling again(Hub(0.010, 0.015), edges, n);
    EXPECT_EQ(again.influence(), first.influence()) << n;
    EXPECT_EQ(again.matrix(), first.matrix()) << n;
    EXPECT_NE(other.influence(), first.influence()) << n;
  }
}

TEST(AxialCoupling, RefusesWhatItCannotModel) {
  const std::vector<double> edges = Edges(10, 1e-3);
  EXPECT_THROW(AxialCoupling(Hub(0.010, 0.010), edges), UserError);
  EXPECT_THROW(AxialCoupling(Hub(0.0, 0.010), edges), UserError);  // a bore loaded, but none
  AxialBody rubber = Shaft(0.010);
  rubber.material.poisson = 0.5;
  EXPECT_THROW(AxialCoupling(rubber, edges), UserError);
  EXPECT_THROW(AxialCoupling(Shaft(0.010), std::vector<double>{0.0}), UserError);
  EXPECT_THROW(AxialCoupling(Shaft(0.010), std::vector<double>{0.0, 1e-3, 1e-3}), UserError);
  EXPECT_THROW(AxialCoupling(Shaft(0.010), Edges(AxialCoupling::kMostRows + 1, 1e-5)), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
