#include "surfaces/cylindrical/coupling_newton.h"

#include <cstring>
#include <random>
#include <vector>

#include <Eigen/LU>

#include "surfaces/cylindrical/elastic/column_sums.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

// Entries uniform in [-1, 1], drawn column by column.
Eigen::MatrixXd Uniform(Eigen::Index rows, Eigen::Index cols, std::mt19937& draw) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixXd a(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) a(i, j) = unit(draw);
  }
  return a;
}

// A system of the analyzer's shape: five components (the breathing mode, then cos and sin of two
// orders), each mode's coupling symmetric positive definite between sections, each section's
// response a positive semidefinite block, and a rank-4 pose term.
CouplingSystem RandomSystem(Eigen::Index sections, unsigned seed) {
  std::mt19937 draw(seed);
  auto random = [&](Eigen::Index rows, Eigen::Index cols) { return Uniform(rows, cols, draw); };
  CouplingSystem system;
  system.Reset(sections, {0, 1, 1, 2, 2});
  for (int mode = 0; mode < 3; ++mode) {
    const Eigen::MatrixXd a = random(sections, sections);
    system.mode_coupling(mode) = 0.1 * a * a.transpose() / static_cast<double>(sections);
    system.mode_coupling(mode).diagonal().array() += 0.2;
  }
  for (Eigen::Index s = 0; s < sections; ++s) {
    const Eigen::MatrixXd r = random(5, 5);
    system.response(s) = r * r.transpose();
  }
  system.pose_out() = 0.1 * random(system.size(), 4);
  system.PoseCoupled();
  system.pose_in() = 0.1 * random(4, system.size());
  return system;
}

TEST(CouplingSystem, ItsProductsAndBlocksAreTheDefinitions) {
  CouplingSystem system = RandomSystem(7, 1);  // its accessors fill it: not const
  const Eigen::MatrixXd dense = system.Dense();
  // Dense() is built from Apply: check it against the definition, I + M diag(R) - out in.
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(system.size(), system.size());
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(system.size(), system.size());
  const std::vector<int> mode_of{0, 1, 1, 2, 2};
  const Eigen::Index n = system.sections();
  for (Eigen::Index c = 0; c < 5; ++c) {
    m.block(c * n, c * n, n, n) = system.mode_coupling(mode_of[static_cast<std::size_t>(c)]);
    for (Eigen::Index s = 0; s < n; ++s) {
      for (Eigen::Index d = 0; d < 5; ++d) {
        r(c * n + s, d * n + s) = system.response(s)(c, d);
      }
    }
  }
  const Eigen::MatrixXd expected = Eigen::MatrixXd::Identity(system.size(), system.size()) + m * r -
                                   system.pose_out() * system.pose_in();
  EXPECT_LE((dense - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  for (Eigen::Index c = 0; c < 5; ++c) {
    EXPECT_LE((system.DiagonalBlock(c) - dense.block(c * n, c * n, n, n)).cwiseAbs().maxCoeff(),
              1e-12 * expected.cwiseAbs().maxCoeff());
  }
}

// The Newton step is solved to the relative residual it is asked for (the analyzer asks for its
// own tolerance, a thousandth), and to rounding when asked for that.
TEST(CouplingSystem, SolvesToTheResidualItIsAskedFor) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const CouplingSystem system = RandomSystem(4 + static_cast<Eigen::Index>(seed % 9), seed);
    const Eigen::MatrixXd dense = system.Dense();
    std::mt19937 draw(100 + seed);
    const Eigen::VectorXd rhs = Uniform(system.size(), 1, draw);
    const Eigen::VectorXd exact = dense.partialPivLu().solve(rhs);
    for (double relative : {1e-3, 1e-6, 1e-12}) {
      const Eigen::VectorXd x = system.Solve(rhs, relative);
      // BiCGSTAB's recursively updated residual may drift from the true one at rounding.
      EXPECT_LE((dense * x - rhs).norm(), 2.0 * relative * rhs.norm() + 1e-13 * rhs.norm())
          << "seed " << seed << ", relative " << relative;
    }
    EXPECT_LE((system.Solve(rhs, 1e-12) - exact).norm(), 1e-9 * exact.norm()) << "seed " << seed;
  }
}

bool SameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// The products the coupling's Newton system takes in Eigen's order give Eigen's bits: every size
// up to and past the 128-column block, right-hand sides with exact zeros (skipped columns) and
// negative zeros, matrices with a zero column.
TEST(ColumnSums, AreEigensProductsBitForBit) {
  std::mt19937 draw(7);
  for (Eigen::Index n : {1, 2, 3, 7, 8, 9, 15, 16, 17, 33, 64, 65, 127, 128, 130}) {
    Eigen::MatrixXd a = Uniform(n, n, draw);
    if (n > 3) a.col(1).setZero();
    Eigen::VectorXd x = Uniform(n, 1, draw);
    x[0] = 0.0;
    if (n > 2) x[2] = -0.0;
    Eigen::VectorXd out(n);
    for (bool skip : {false, true}) {
      TimesInOrder(a, x.data(), out.data(), skip);
      const Eigen::VectorXd eigen = a * x;
      EXPECT_TRUE(SameBits(out, eigen)) << n << (skip ? " skipping zeros" : "");
      // Rows 1/3 .. 2/3 alone: the whole product's entries there.
      const Eigen::Index first = n / 3, count = n - 2 * (n / 3);
      Eigen::VectorXd part = eigen;
      part.segment(first, count).setConstant(-1.0);
      TimesInOrder(a, x.data(), part.data(), first, count, skip);
      EXPECT_TRUE(SameBits(part.segment(first, count), eigen.segment(first, count))) << n;
    }
  }
  // A rectangular matrix and one of a single row (Eigen's inner product there).
  const Eigen::MatrixXd wide = Uniform(3, 140, draw), row = Uniform(1, 5, draw);
  const Eigen::VectorXd x = Uniform(140, 1, draw);
  Eigen::VectorXd out(3), one(1);
  TimesInOrder(wide, x.data(), out.data());
  EXPECT_TRUE(SameBits(out, wide * x));
  TimesInOrder(row, x.data(), one.data());
  EXPECT_TRUE(SameBits(one, row * x.head(5)));
}

}  // namespace
}  // namespace fitfeel::cylindrical
