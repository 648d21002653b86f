#include "framework/metrology/circle_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "framework/metrology/linear_program.h"

namespace fitfeel::metrology {
namespace {

Circle AlgebraicCircle(const Eigen::Matrix2Xd& p) {
  // x^2 + y^2 + D x + E y + F = 0 in the least-squares sense, in coordinates about the centroid
  // for conditioning.
  const Eigen::Vector2d mean = p.rowwise().mean();
  const long n = p.cols();
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd rhs(n);
  for (long i = 0; i < n; ++i) {
    const Eigen::Vector2d q = p.col(i) - mean;
    A(i, 0) = q.x();
    A(i, 1) = q.y();
    A(i, 2) = 1.0;
    rhs(i) = -q.squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(rhs);
  Circle c;
  c.centre = mean + Eigen::Vector2d(-s(0) / 2.0, -s(1) / 2.0);
  const double r2 = (s(0) * s(0) + s(1) * s(1)) / 4.0 - s(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) throw std::invalid_argument("points are collinear");
  c.radius = std::sqrt(r2);
  return c;
}

}  // namespace

Circle LeastSquaresCircle(const Eigen::Matrix2Xd& points) {
  if (points.cols() < 3) throw std::invalid_argument("a circle fit needs at least 3 points");
  if (!points.allFinite()) throw std::invalid_argument("circle fit: non-finite point");
  {
    const Eigen::Matrix2Xd q = points.colwise() - points.rowwise().mean();
    const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(q * q.transpose())
                                   .eigenvalues();  // ascending
    if (!(ev(0) > 1e-20 * ev(1))) throw std::invalid_argument("circle fit: points are collinear");
  }
  Circle c = AlgebraicCircle(points);
  const long n = points.cols();
  Eigen::MatrixXd J(n, 3);
  Eigen::VectorXd res(n);
  for (int it = 0; it < 100; ++it) {
    for (long i = 0; i < n; ++i) {
      const Eigen::Vector2d q = points.col(i) - c.centre;
      const double d = q.norm();
      if (d == 0.0) throw std::invalid_argument("circle fit: a point lies at the centre");
      res(i) = d - c.radius;
      J(i, 0) = -q.x() / d;
      J(i, 1) = -q.y() / d;
      J(i, 2) = -1.0;
    }
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(-res);
    c.centre += step.head<2>();
    c.radius += step(2);
    if (step.norm() <= 1e-15 * (c.radius + c.centre.norm())) break;
  }
  return c;
}

RoundnessResult MinimumZoneRoundness(const Eigen::Matrix2Xd& points) {
  const long n = points.cols();
  if (n < 4) throw std::invalid_argument("roundness needs at least 4 points");
  if (!points.allFinite()) throw std::invalid_argument("roundness: non-finite point");
  RoundnessResult out;
  // The algebraic circle is start enough: the steps below recentre to the minimum zone's centre.
  out.centre = AlgebraicCircle(points).centre;
  Eigen::VectorXd rho(n), cs(n), sn(n);
  auto polar = [&]() {
    for (long i = 0; i < n; ++i) {
      const Eigen::Vector2d q = points.col(i) - out.centre;
      rho(i) = q.norm();
      cs(i) = q.x() / rho(i);
      sn(i) = q.y() / rho(i);
    }
  };
  // Variables (a, b, r_in, r_out) in units of `scale`, deviations from the mean radius.
  const Eigen::Vector4d c(0.0, 0.0, -1.0, 1.0);
  Eigen::VectorXd dev(n);
  std::vector<long> order(static_cast<std::size_t>(n));
  std::vector<char> in_set(static_cast<std::size_t>(n));
  std::vector<long> set;
  for (int step = 0; step < 8; ++step) {
    polar();
    const double mean = rho.mean();
    const double scale = (rho.array() - mean).abs().maxCoeff();
    if (scale <= 1e-15 * mean) break;  // perfectly round to rounding
    dev = (rho.array() - mean) / scale;
    // The zone is held by a few points (four, generically): the program is solved over a working
    // set, first the points farthest out and in, then with every point the solution leaves
    // outside its zone added, until none is. The optimum of such a relaxation that every point
    // satisfies is the whole program's (the same constraints, fewer rows to pivot through).
    std::iota(order.begin(), order.end(), 0L);
    const long k = std::min<long>(n, 8);
    std::partial_sort(order.begin(), order.begin() + k, order.end(),
                      [&](long i, long j) { return dev(i) > dev(j); });
    set.assign(order.begin(), order.begin() + k);
    std::partial_sort(order.begin(), order.begin() + k, order.end(),
                      [&](long i, long j) { return dev(i) < dev(j); });
    std::fill(in_set.begin(), in_set.end(), 0);
    for (long i : set) in_set[static_cast<std::size_t>(i)] = 1;
    for (long j = 0; j < k; ++j) {
      const long i = order[static_cast<std::size_t>(j)];
      if (!in_set[static_cast<std::size_t>(i)]) {
        set.push_back(i);
        in_set[static_cast<std::size_t>(i)] = 1;
      }
    }
    LinearProgramResult lp;
    for (;;) {
      const long m = static_cast<long>(set.size());
      Eigen::MatrixXd A(2 * m, 4);
      Eigen::VectorXd b(2 * m);
      for (long r = 0; r < m; ++r) {
        const long i = set[static_cast<std::size_t>(r)];
        // dev - a cos - b sin <= r_out
        A.row(2 * r) << -cs(i), -sn(i), 0.0, -1.0;
        b(2 * r) = -dev(i);
        // r_in <= dev - a cos - b sin
        A.row(2 * r + 1) << cs(i), sn(i), 1.0, 0.0;
        b(2 * r + 1) = dev(i);
      }
      lp = MinimiseLinearProgram(c, A, b);
      // Points outside the zone found (beyond rounding: deviations are of order 1 here).
      bool added = false;
      for (long i = 0; i < n; ++i) {
        if (in_set[static_cast<std::size_t>(i)]) continue;
        const double e = dev(i) - lp.x(0) * cs(i) - lp.x(1) * sn(i);
        if (e > lp.x(3) + 1e-12 || e < lp.x(2) - 1e-12) {
          set.push_back(i);
          in_set[static_cast<std::size_t>(i)] = 1;
          added = true;
        }
      }
      if (!added) break;
    }
    const Eigen::Vector2d shift = lp.x.head<2>() * scale;
    out.centre += shift;
    if (shift.norm() <= 1e-9 * scale + 1e-15 * mean) break;
  }
  polar();
  out.inner_radius = rho.minCoeff();
  out.outer_radius = rho.maxCoeff();
  out.value = out.outer_radius - out.inner_radius;
  return out;
}

}  // namespace fitfeel::metrology
