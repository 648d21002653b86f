#include "framework/metrology/linear_program.h"

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace fitfeel::metrology {
namespace {

TEST(LinearProgram, SolvesATextbookProgram) {
  // max 3x + 5y s.t. x <= 4, 2y <= 12, 3x + 2y <= 18 (and x, y >= 0): optimum (2, 6), 36.
  Eigen::MatrixXd A(5, 2);
  A << 1, 0, 0, 2, 3, 2, -1, 0, 0, -1;
  Eigen::VectorXd b(5);
  b << 4, 12, 18, 0, 0;
  const auto r = MinimiseLinearProgram(Eigen::Vector2d(-3, -5), A, b);
  EXPECT_NEAR(r.x(0), 2.0, 1e-12);
  EXPECT_NEAR(r.x(1), 6.0, 1e-12);
  EXPECT_NEAR(r.objective, -36.0, 1e-12);
}

TEST(LinearProgram, ChebyshevLineFitHandlesNegativeCosts) {
  // min t s.t. |y_i - (a + b x_i)| <= t for points on y = x^2 at x = -1, 0, 1: the best line is
  // y = 0.5 with t = 0.5 (equioscillation at three points).
  const double xs[] = {-1, 0, 1};
  Eigen::MatrixXd A(6, 3);
  Eigen::VectorXd b(6);
  for (int i = 0; i < 3; ++i) {
    const double y = xs[i] * xs[i];
    A.row(2 * i) << -1, -xs[i], -1;  // y - a - b x <= t
    b(2 * i) = -y;
    A.row(2 * i + 1) << 1, xs[i], -1;  // a + b x - y <= t
    b(2 * i + 1) = y;
  }
  const auto r = MinimiseLinearProgram(Eigen::Vector3d(0, 0, 1), A, b);
  EXPECT_NEAR(r.x(0), 0.5, 1e-12);
  EXPECT_NEAR(r.x(1), 0.0, 1e-12);
  EXPECT_NEAR(r.objective, 0.5, 1e-12);
}

TEST(LinearProgram, RefusesUnboundedAndInfeasiblePrograms) {
  Eigen::MatrixXd A(1, 1);
  A << 1;
  // min -x s.t. x >= ... nothing below: unbounded.
  EXPECT_THROW(MinimiseLinearProgram(Eigen::VectorXd::Constant(1, 1.0), A,
                                     Eigen::VectorXd::Constant(1, 1.0)),
               std::runtime_error);
  Eigen::MatrixXd B(2, 1);
  B << 1, -1;  // x <= -1 and x >= 1
  EXPECT_THROW(
      MinimiseLinearProgram(Eigen::VectorXd::Constant(1, 1.0), B, Eigen::Vector2d(-1.0, -1.0)),
      std::runtime_error);
}

// A cutting-plane loop's programs, cold and warm: the smallest disc holding random points, each
// point's circle replaced by tangent half-planes, the farthest point's tangent added each round.
// Warm-started from the last round's basis the optimum is the cold solve's in fewer pivots. A
// basis that does not fit (wrong size, a row out of range or repeated) is ignored, and one of any
// three rows (feasible or not) still ends at the cold optimum.
TEST(LinearProgram, AWarmStartedCuttingPlaneLoopReachesTheColdOptimumInFewerPivots) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int points = 30;
  std::vector<Eigen::Vector2d> p(points);
  for (auto& q : p) q = Eigen::Vector2d(uniform(rng), uniform(rng));
  // Variables (x, z, r): |p_i - (x, z)| <= r as cuts u . (p_i - (x, z)) <= r.
  std::vector<Eigen::RowVector3d> rows;
  std::vector<double> rhs;
  auto cut = [&](int i, const Eigen::Vector2d& u) {
    rows.emplace_back(-u.x(), -u.y(), -1.0);
    rhs.push_back(-u.dot(p[i]));
  };
  for (int i = 0; i < points; ++i) {
    for (int q = 0; q < 4; ++q)
      cut(i, Eigen::Vector2d(std::cos(q * M_PI / 2), std::sin(q * M_PI / 2)));
  }
  // The program of the cuts so far.
  auto program = [&] {
    Eigen::MatrixXd A(rows.size(), 3);
    Eigen::VectorXd b(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      A.row(static_cast<Eigen::Index>(k)) = rows[k];
      b(static_cast<Eigen::Index>(k)) = rhs[k];
    }
    return std::pair{A, b};
  };
  const Eigen::Vector3d c(0.0, 0.0, 1.0);
  std::vector<int> basis;
  int cold_pivots = 0, warm_pivots = 0, rounds = 0;
  for (; rounds < 200; ++rounds) {
    const auto [A, b] = program();
    const LinearProgramResult cold = MinimiseLinearProgram(c, A, b);
    const LinearProgramResult warm = MinimiseLinearProgram(c, A, b, &basis);
    ASSERT_EQ(basis.size(), 3u);
    EXPECT_NEAR(warm.objective, cold.objective, 1e-12);
    cold_pivots += cold.iterations;
    warm_pivots += warm.iterations;
    // The farthest point from the warm optimum's centre gets its tangent.
    const Eigen::Vector2d centre = warm.x.head<2>();
    int far = 0;
    for (int i = 1; i < points; ++i) {
      if ((p[i] - centre).norm() > (p[far] - centre).norm()) far = i;
    }
    if ((p[far] - centre).norm() <= warm.x(2) * (1.0 + 1e-12)) break;
    cut(far, (p[far] - centre).normalized());
  }
  EXPECT_GT(rounds, 5);
  EXPECT_LT(2 * warm_pivots, cold_pivots);

  // Other starts: the cold answer.
  const auto [A, b] = program();
  const LinearProgramResult cold = MinimiseLinearProgram(c, A, b);
  const int n = static_cast<int>(rows.size());
  for (std::vector<int> bad :
       {std::vector<int>{0, 1}, std::vector<int>{0, 1, n}, std::vector<int>{0, 0, 1},
        std::vector<int>{0, 1, 2}, std::vector<int>{-1, 1, 2}}) {
    const LinearProgramResult r = MinimiseLinearProgram(c, A, b, &bad);
    EXPECT_NEAR(r.objective, cold.objective, 1e-12);
    EXPECT_EQ(bad.size(), 3u);
  }
}

}  // namespace
}  // namespace fitfeel::metrology
