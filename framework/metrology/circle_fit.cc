#include "framework/metrology/circle_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "framework/metrology/linear_program.h"

namespace fitfeel::metrology {
namespace {

// The least-squares solution of the n x 3 system a x = b by its normal equations a'a x = a'b,
// accumulated row by row (`row(i, &v, &b)` gives row i and its right-hand side): a tenth of a QR's
// cost on a section's few hundred points. Squaring the condition costs the fits nothing they
// keep: the algebraic circle only starts the geometric fits, and Gauss-Newton's fixed point is the
// stationary point whatever the rounding of its steps (tested on arcs down to 0.2 degrees). Where
// the normal matrix is singular to rounding (points on a line), the QR's rank-revealing solve.
template <typename Row>
Eigen::Vector3d SolveThreeColumns(long n, const Row& row) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  Eigen::Vector3d v;
  double b = 0.0;
  for (long i = 0; i < n; ++i) {
    row(i, &v, &b);
    ata.noalias() += v * v.transpose();
    atb += b * v;
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(ata);
  if (ldlt.info() == Eigen::Success && ldlt.rcond() > 1e-12) return ldlt.solve(atb);
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd rhs(n);
  for (long i = 0; i < n; ++i) {
    row(i, &v, &b);
    a.row(i) = v.transpose();
    rhs(i) = b;
  }
  return a.colPivHouseholderQr().solve(rhs);
}

Circle AlgebraicCircle(const Eigen::Matrix2Xd& p) {
  // x^2 + y^2 + D x + E y + F = 0 in the least-squares sense, in coordinates about the centroid
  // for conditioning.
  const Eigen::Vector2d mean = p.rowwise().mean();
  const Eigen::Vector3d s = SolveThreeColumns(p.cols(), [&](long i, Eigen::Vector3d* v, double* b) {
    const Eigen::Vector2d q = p.col(i) - mean;
    *v << q.x(), q.y(), 1.0;
    *b = -q.squaredNorm();
  });
  Circle c;
  c.centre = mean + Eigen::Vector2d(-s(0) / 2.0, -s(1) / 2.0);
  const double r2 = (s(0) * s(0) + s(1) * s(1)) / 4.0 - s(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) throw std::invalid_argument("points are collinear");
  c.radius = std::sqrt(r2);
  return c;
}

// The limacon linearisation's minimum zone as a Chebyshev (minimax) fit: (a, b, c) minimising
// max |dev - a cos - b sin - c| over the points, by Remez's exchange. 1, cos and sin span a Haar
// space on the circle (three distinct angles never leave their 3 x 3 system singular), so the fit
// is unique and is levelled on four points whose errors alternate in sign around the circle; each
// exchange swaps the worst point into that reference, keeping the alternation, and the levelled
// error grows until no point exceeds it. It replaces the 4-variable linear program the same
// problem is (the same optimum; about a tenth of its cost on 360 points). Returns false without
// convergence (a degenerate reference: coincident angles), for the program to take over.
// `order` and `reference` carry the angular order and the last reference from one recentring step
// to the next (the centre moves micrometres: the same order, and usually the same four points).
bool ChebyshevOnCircle(const Eigen::VectorXd& cs, const Eigen::VectorXd& sn,
                       const Eigen::VectorXd& dev, std::vector<long>* order,
                       std::array<long, 4>* reference, Eigen::Vector4d* x) {
  const long n = dev.size();
  std::array<long, 4>& ref = *reference;
  if (static_cast<long>(order->size()) != n) {
    order->resize(static_cast<std::size_t>(n));
    std::iota(order->begin(), order->end(), 0L);
    // Points given in angular order (a section's columns) turn once around the centre, each a
    // positive step from the last: then no angles need sorting.
    // (Each step turning by less than half a turn, the times the directions cross the +x axis
    // upwards count the turns.)
    int turns = 0;
    bool ordered = true;
    for (long i = 0; i < n && ordered; ++i) {
      const long j = (i + 1) % n;
      ordered = cs(i) * sn(j) - sn(i) * cs(j) > 0.0;
      if (sn(i) < 0.0 && sn(j) >= 0.0 && cs(i) + cs(j) > 0.0) ++turns;
    }
    if (!ordered || turns != 1) {
      std::vector<double> angle(static_cast<std::size_t>(n));
      for (long i = 0; i < n; ++i) angle[static_cast<std::size_t>(i)] = std::atan2(sn(i), cs(i));
      std::sort(order->begin(), order->end(), [&](long i, long j) {
        return angle[static_cast<std::size_t>(i)] < angle[static_cast<std::size_t>(j)];
      });
    }
    ref = {0, n / 4, n / 2, (3 * n) / 4};  // positions in angular order, increasing
  }
  for (int iteration = 0; iteration < 100; ++iteration) {
    Eigen::Matrix4d m;
    Eigen::Vector4d rhs;
    for (int k = 0; k < 4; ++k) {
      const long i = (*order)[static_cast<std::size_t>(ref[static_cast<std::size_t>(k)])];
      m.row(k) << cs(i), sn(i), 1.0, (k % 2 == 0) ? 1.0 : -1.0;
      rhs(k) = dev(i);
    }
    const Eigen::FullPivLU<Eigen::Matrix4d> lu(m);
    if (!lu.isInvertible()) return false;
    const Eigen::Vector4d abch = lu.solve(rhs);  // a, b, c, h
    if (!abch.allFinite()) return false;
    const double level = std::abs(abch(3));
    long worst = -1;
    double worst_error = level;
    for (long p = 0; p < n; ++p) {
      const long i = (*order)[static_cast<std::size_t>(p)];
      const double e = std::abs(dev(i) - abch(0) * cs(i) - abch(1) * sn(i) - abch(2));
      if (e > worst_error) {
        worst_error = e;
        worst = p;
      }
    }
    // Deviations are scaled to order 1: 1e-12 beyond the level is rounding.
    if (worst < 0 || worst_error <= level + 1e-12) {
      *x << abch(0), abch(1), abch(2) - level, abch(2) + level;
      return true;
    }
    // The reference interval (cyclic) holding the worst point: ref[k] <= worst < ref[k + 1].
    int k = 3;
    for (int q = 0; q < 3; ++q) {
      if (ref[static_cast<std::size_t>(q)] <= worst &&
          worst < ref[static_cast<std::size_t>(q) + 1]) {
        k = q;
      }
    }
    const long i = (*order)[static_cast<std::size_t>(worst)];
    const double sign = dev(i) - abch(0) * cs(i) - abch(1) * sn(i) - abch(2) > 0.0 ? 1.0 : -1.0;
    // The residual at ref[k] is +h for even k, -h for odd k.
    const double at_k = ((k % 2 == 0) ? 1.0 : -1.0) * (abch(3) >= 0.0 ? 1.0 : -1.0);
    const int replace = sign == at_k ? k : (k + 1) % 4;
    ref[static_cast<std::size_t>(replace)] = worst;
    std::sort(ref.begin(), ref.end());
    // Sorting may rotate which point is "even": the levelled system's signs follow the positions,
    // and an exchange that keeps the alternation keeps it under any rotation of the four.
  }
  return false;
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
  for (int it = 0; it < 100; ++it) {
    // Gauss-Newton on the radial residuals d_i - R: rows (-q / d, -1) of the Jacobian.
    const Eigen::Vector3d step = SolveThreeColumns(n, [&](long i, Eigen::Vector3d* v, double* b) {
      const Eigen::Vector2d q = points.col(i) - c.centre;
      const double d = q.norm();
      if (d == 0.0) throw std::invalid_argument("circle fit: a point lies at the centre");
      *v << -q.x() / d, -q.y() / d, -1.0;
      *b = -(d - c.radius);
    });
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
  // The points about the centre, as whole arrays (vectorised: point by point, the divisions' and
  // the square root's latency was most of this function's own time).
  Eigen::ArrayXd dx(n), dy(n);
  auto polar = [&]() {
    dx = points.row(0).transpose().array() - out.centre.x();
    dy = points.row(1).transpose().array() - out.centre.y();
    rho.array() = (dx.square() + dy.square()).sqrt();
    cs.array() = dx / rho.array();
    sn.array() = dy / rho.array();
  };
  // Variables (a, b, r_in, r_out) in units of `scale`, deviations from the mean radius.
  const Eigen::Vector4d c(0.0, 0.0, -1.0, 1.0);
  Eigen::VectorXd dev(n);
  std::vector<long> order(static_cast<std::size_t>(n));
  std::vector<char> in_set(static_cast<std::size_t>(n));
  std::vector<long> set;
  std::vector<long> angular;  // the exchange's angular order and reference, kept between steps
  std::array<long, 4> reference{};
  for (int step = 0; step < 8; ++step) {
    polar();
    const double mean = rho.mean();
    const double scale = (rho.array() - mean).abs().maxCoeff();
    if (scale <= 1e-15 * mean) break;  // perfectly round to rounding
    dev = (rho.array() - mean) / scale;
    if (Eigen::Vector4d fit; ChebyshevOnCircle(cs, sn, dev, &angular, &reference, &fit)) {
      const Eigen::Vector2d shift = fit.head<2>() * scale;
      out.centre += shift;
      if (shift.norm() <= 1e-9 * scale + 1e-15 * mean) break;
      continue;
    }
    LinearProgramResult lp;
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
    std::vector<int> basis;  // the last pass's, for the next (its rows only gain points)
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
      lp = MinimiseLinearProgram(c, A, b, &basis);
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
