#include "framework/metrology/linear_program.h"

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

}  // namespace
}  // namespace fitfeel::metrology
