#include "framework/metrology/circle_fit.h"

#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "framework/metrology/linear_program.h"
#include "framework/testing/units.h"

namespace fitfeel::metrology {
namespace {

using test_support::kPi;

// r = R + a cos(k theta) about `centre`: minimum-zone roundness 2a (docs/oracles.md), whatever the
// centre, because the 2k alternating extremes satisfy the Chebyshev alternation criterion.
Eigen::Matrix2Xd Lobed(double R, double a, int k, const Eigen::Vector2d& centre, int n) {
  Eigen::Matrix2Xd p(2, n);
  for (int j = 0; j < n; ++j) {
    const double t = 2.0 * kPi * j / n;
    const double r = R + a * std::cos(k * t);
    p.col(j) = centre + r * Eigen::Vector2d(std::cos(t), std::sin(t));
  }
  return p;
}

// r = R + a cos(k theta) about `centre`: minimum-zone roundness 2a (docs/oracles.md), whatever the
// centre. 840 points so that every extreme of every k tested is sampled (2k divides 840).
TEST(MinimumZoneRoundness, LobedProfilesGiveTwiceTheAmplitude) {
  for (int k = 2; k <= 7; ++k) {
    for (const Eigen::Vector2d& centre :
         {Eigen::Vector2d(0, 0), Eigen::Vector2d(3e-4, -2e-4), Eigen::Vector2d(-5.0, 12.0)}) {
      const auto r = MinimumZoneRoundness(Lobed(0.01, 5e-6, k, centre, 840));
      EXPECT_NEAR(r.value, 1e-5, 1e-11) << "k=" << k << " centre " << centre.transpose();
      EXPECT_NEAR((r.centre - centre).norm(), 0.0, 1e-9);
    }
  }
}

TEST(MinimumZoneRoundness, IsBelowTheLeastSquaresZone) {
  // Sum of harmonics: the minimum zone is never wider than the zone about the LS centre, and for
  // this non-symmetric profile strictly narrower.
  const int n = 400;
  Eigen::Matrix2Xd p(2, n);
  for (int j = 0; j < n; ++j) {
    const double t = 2.0 * kPi * j / n;
    const double r =
        0.02 + 3e-6 * std::cos(2 * t + 0.3) + 2e-6 * std::cos(3 * t + 1.1) + 1e-6 * std::sin(5 * t);
    p.col(j) = r * Eigen::Vector2d(std::cos(t), std::sin(t));
  }
  const Circle ls = LeastSquaresCircle(p);
  const Eigen::VectorXd d = (p.colwise() - ls.centre).colwise().norm();
  const double ls_zone = d.maxCoeff() - d.minCoeff();
  const auto mz = MinimumZoneRoundness(p);
  EXPECT_LE(mz.value, ls_zone + 1e-15);
  EXPECT_GT(mz.value, 0.5 * ls_zone);
}

// The zone found is the linear program's optimum on every point (the exchange that finds it works
// on four): about the returned centre, the program over all points neither moves the centre nor
// narrows the zone. Random sections: harmonics to 30 with noise, 4 to 720 points, unequal angles,
// a third of them shuffled.
TEST(MinimumZoneRoundness, NoPointProgramImprovesOnTheZoneFound) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = trial < 20 ? 4 + trial : 8 + static_cast<int>(712 * u(rng));
    const double radius = 1e-3 + 0.05 * u(rng);
    Eigen::Matrix2Xd p(2, n);
    std::vector<std::array<double, 3>> harmonics(1 + static_cast<int>(6 * u(rng)));
    for (auto& h : harmonics) h = {std::floor(1 + 30 * u(rng)), 5e-6 * u(rng), 2 * kPi * u(rng)};
    const Eigen::Vector2d centre(1e-3 * (u(rng) - 0.5), 1e-3 * (u(rng) - 0.5));
    for (int j = 0; j < n; ++j) {
      const double t = 2.0 * kPi * (j + 0.8 * (u(rng) - 0.5)) / n;
      double r = radius + 1e-7 * (u(rng) - 0.5);
      for (const auto& [k, a, phase] : harmonics) r += a * std::cos(k * t + phase);
      p.col(j) = centre + r * Eigen::Vector2d(std::cos(t), std::sin(t));
    }
    if (trial % 3 == 0) {  // points in no particular order (the exchange sorts their angles)
      for (int j = n - 1; j > 0; --j)
        p.col(j).swap(p.col(static_cast<int>(u(rng) * (j + 1)) % (j + 1)));
    }
    const RoundnessResult mz = MinimumZoneRoundness(p);
    // The program about mz.centre: shift (a, b), radii r_in <= rho - a cos - b sin <= r_out.
    Eigen::MatrixXd A(2 * n, 4);
    Eigen::VectorXd b(2 * n);
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d q = p.col(j) - mz.centre;
      const double rho = q.norm(), c = q.x() / rho, s = q.y() / rho;
      A.row(2 * j) << -c, -s, 0.0, -1.0;
      b(2 * j) = -(rho - radius);
      A.row(2 * j + 1) << c, s, 1.0, 0.0;
      b(2 * j + 1) = rho - radius;
    }
    const LinearProgramResult lp =
        MinimiseLinearProgram(Eigen::Vector4d(0.0, 0.0, -1.0, 1.0), A, b);
    const double scale = std::max(mz.value, 1e-9);
    EXPECT_GE(lp.objective, mz.value - 1e-9 * scale) << "trial " << trial << " n " << n;
    EXPECT_LT(lp.x.head<2>().norm(), 1e-6 * scale + 1e-15) << "trial " << trial << " n " << n;
    EXPECT_NEAR(mz.value, mz.outer_radius - mz.inner_radius, 1e-15);
  }
}

// Points c + (r + e_i) u(theta_i) on an arc with residuals e orthogonal to {1, cos, sin}: then
// (c, r) is exactly a stationary point of the geometric least-squares objective (its gradient is
// -2 sum e_i (1, u_i)), so the fit must return it. The algebraic fit is biased on such an arc and
// must not be what we return. (NIST cir2d1 is not available offline.)
Circle FitOnArc(double degrees, const Eigen::Vector2d& c, double r, double noise_amplitude) {
  const int n = 38;
  Eigen::MatrixXd basis(n, 3);
  Eigen::VectorXd noise(n);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd theta(n);
  for (int i = 0; i < n; ++i) {
    theta(i) = 0.2 + (degrees * kPi / 180.0) * i / (n - 1);
    basis.row(i) << 1.0, std::cos(theta(i)), std::sin(theta(i));
    noise(i) = noise_amplitude * u(rng);
  }
  const Eigen::MatrixXd Q = basis.householderQr().householderQ() * Eigen::MatrixXd::Identity(n, 3);
  const Eigen::VectorXd e = noise - Q * (Q.transpose() * noise);
  Eigen::Matrix2Xd p(2, n);
  for (int i = 0; i < n; ++i)
    p.col(i) = c + (r + e(i)) * Eigen::Vector2d(std::cos(theta(i)), std::sin(theta(i)));
  return LeastSquaresCircle(p);
}

TEST(LeastSquaresCircle, RecoversAKnownGeometricFitOnAPartialArc) {
  const Eigen::Vector2d c(-560.3177272525, 34.2390233302);
  const double r = 13.29077564385;
  const Circle fit = FitOnArc(70.0, c, r, 0.05);
  EXPECT_NEAR(fit.centre.x(), c.x(), 1e-9);
  EXPECT_NEAR(fit.centre.y(), c.y(), 1e-9);
  EXPECT_NEAR(fit.radius, r, 1e-9);
}

// A short arc leaves the fit's three columns nearly dependent (the Gauss-Newton steps solve their
// normal equations, which square the condition): the fit still converges to the stationary point.
TEST(LeastSquaresCircle, RecoversItOnAShortArc) {
  const Eigen::Vector2d c(0.3, -0.2);
  const double r = 10.0;
  for (double degrees : {20.0, 5.0, 1.0, 0.2}) {
    const Circle fit = FitOnArc(degrees, c, r, 1e-4);
    EXPECT_NEAR(fit.centre.x(), c.x(), 1e-7) << degrees;
    EXPECT_NEAR(fit.centre.y(), c.y(), 1e-7) << degrees;
    EXPECT_NEAR(fit.radius, r, 1e-7) << degrees;
  }
}

TEST(LeastSquaresCircle, RefusesCollinearPoints) {
  Eigen::Matrix2Xd p(2, 4);
  p << 0, 1, 2, 3, 0, 1, 2, 3;
  EXPECT_THROW(LeastSquaresCircle(p), std::invalid_argument);
  EXPECT_THROW(LeastSquaresCircle(p.leftCols(2)), std::invalid_argument);
}

}  // namespace
}  // namespace fitfeel::metrology
