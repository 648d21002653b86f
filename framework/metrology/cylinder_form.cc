#include "framework/metrology/cylinder_form.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "framework/metrology/circle_fit.h"
#include "framework/metrology/linear_program.h"

namespace fitfeel::metrology {
namespace {

void CheckSamples(const CylinderSamples& s) {
  if (s.y.size() < 1 || s.theta.size() < 1 || s.deviation.rows() != s.y.size() ||
      s.deviation.cols() != s.theta.size()) {
    throw std::invalid_argument("cylinder samples: inconsistent dimensions");
  }
  if (!(s.nominal_radius > 0.0) || !s.deviation.allFinite()) {
    throw std::invalid_argument("cylinder samples: need a positive radius and finite deviations");
  }
}

// Maps y to [-1, 1] for conditioning: returns (centre, half-span).
std::pair<double, double> AxialScale(const Eigen::VectorXd& y) {
  const double lo = y.minCoeff(), hi = y.maxCoeff();
  const double half = (hi - lo) / 2.0;
  return {(hi + lo) / 2.0, half > 0.0 ? half : 1.0};
}

// Largest distance of the centres from the line p0 + t * y.
double MaxDistance(const Eigen::VectorXd& y, const Eigen::Matrix2Xd& c, const Eigen::Vector2d& p0,
                   const Eigen::Vector2d& t) {
  // Distance from the line in 3-D (y, x, z) space with direction (1, t).
  const Eigen::Vector3d dir = Eigen::Vector3d(1.0, t.x(), t.y()).normalized();
  double worst = 0.0;
  for (long i = 0; i < c.cols(); ++i) {
    const Eigen::Vector3d d(0.0, c(0, i) - p0.x() - t.x() * y(i), c(1, i) - p0.y() - t.y() * y(i));
    worst = std::max(worst, (d - d.dot(dir) * dir).norm());
  }
  return worst;
}

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

Eigen::Matrix2Xd CylinderSamples::Directions() const {
  Eigen::Matrix2Xd d(2, theta.size());
  for (long j = 0; j < theta.size(); ++j) {
    d(0, j) = std::cos(theta(j));
    d(1, j) = std::sin(theta(j));
  }
  return d;
}

Eigen::Matrix2Xd CylinderSamples::SectionPoints(int row) const {
  return SectionPoints(row, Directions());
}

Eigen::Matrix2Xd CylinderSamples::SectionPoints(int row, const Eigen::Matrix2Xd& directions) const {
  Eigen::Matrix2Xd p(2, theta.size());
  for (long j = 0; j < theta.size(); ++j) {
    const double r = nominal_radius + deviation(row, j);
    p(0, j) = r * directions(0, j);
    p(1, j) = r * directions(1, j);
  }
  return p;
}

CylindricityResult MinimumZoneCylindricity(const CylinderSamples& s) {
  CheckSamples(s);
  const long m = s.y.size(), n = s.theta.size();
  CylindricityResult out;
  const double scale = s.deviation.cwiseAbs().maxCoeff();
  if (scale == 0.0) return out;
  const auto [yc, yh] = AxialScale(s.y);
  // Variables (a, b, c, d, r_in, r_out): axis x = a + b*u, z = c + d*u with u = (y - yc)/yh.
  // Constraint generation: most of the 2 m n constraints are slack at the optimum, so the LP is
  // solved on a working set (each row's highest and lowest point to start), every point is then
  // checked against the solution, and the most violated are added until none is: the last LP's
  // optimum is then the full program's.
  Eigen::VectorXd u(m);
  for (long i = 0; i < m; ++i) u(i) = (s.y(i) - yc) / yh;
  const Eigen::Matrix2Xd directions = s.Directions();
  const auto cs = directions.row(0), sn = directions.row(1);
  const Eigen::MatrixXd v = s.deviation / scale;
  std::vector<char> in_set(m * n, 0);
  std::vector<long> working;
  auto add = [&](long i, long j) {
    if (!in_set[i * n + j]) {
      in_set[i * n + j] = 1;
      working.push_back(i * n + j);
    }
  };
  for (long i = 0; i < m; ++i) {
    Eigen::Index hi_j = 0, lo_j = 0;
    v.row(i).maxCoeff(&hi_j);
    v.row(i).minCoeff(&lo_j);
    add(i, hi_j);
    add(i, lo_j);
  }
  Eigen::VectorXd c(6);
  c << 0, 0, 0, 0, -1, 1;
  Eigen::VectorXd x;
  Eigen::MatrixXd residual(m, n);
  std::vector<int> basis;  // the last round's, for the next (its rows only gain points)
  for (int round = 0; round < 200; ++round) {
    const long w = static_cast<long>(working.size());
    Eigen::MatrixXd A(2 * w, 6);
    Eigen::VectorXd rhs(2 * w);
    for (long k = 0; k < w; ++k) {
      const long i = working[k] / n, j = working[k] % n;
      A.row(2 * k) << -cs(j), -cs(j) * u(i), -sn(j), -sn(j) * u(i), 0.0, -1.0;  // <= r_out
      rhs(2 * k) = -v(i, j);
      A.row(2 * k + 1) << cs(j), cs(j) * u(i), sn(j), sn(j) * u(i), 1.0, 0.0;  // >= r_in
      rhs(2 * k + 1) = v(i, j);
    }
    x = MinimiseLinearProgram(c, A, rhs, &basis).x;
    for (long i = 0; i < m; ++i)
      for (long j = 0; j < n; ++j)
        residual(i, j) = v(i, j) - (x(0) + x(1) * u(i)) * cs(j) - (x(2) + x(3) * u(i)) * sn(j);
    // Violations beyond rounding, worst first, at most 2 m per round.
    std::vector<std::pair<double, long>> violated;
    for (long i = 0; i < m; ++i)
      for (long j = 0; j < n; ++j) {
        const double over = std::max(residual(i, j) - x(5), x(4) - residual(i, j));
        if (over > 1e-12 && !in_set[i * n + j]) violated.emplace_back(-over, i * n + j);
      }
    if (violated.empty()) break;
    const size_t take = std::min<size_t>(violated.size(), 2 * m);
    std::partial_sort(violated.begin(), violated.begin() + take, violated.end());
    for (size_t k = 0; k < take; ++k) add(violated[k].second / n, violated[k].second % n);
  }
  const double lo = residual.minCoeff(), hi = residual.maxCoeff();
  out.value = (hi - lo) * scale;
  out.tx = x(1) * scale / yh;
  out.x0 = x(0) * scale - out.tx * yc;
  out.tz = x(3) * scale / yh;
  out.z0 = x(2) * scale - out.tz * yc;
  return out;
}

Eigen::Matrix2Xd SectionCentres(const CylinderSamples& s) {
  CheckSamples(s);
  Eigen::Matrix2Xd centres(2, s.y.size());
  const Eigen::Matrix2Xd directions = s.Directions();
  for (long i = 0; i < s.y.size(); ++i) {
    centres.col(i) = LeastSquaresCircle(s.SectionPoints(static_cast<int>(i), directions)).centre;
  }
  return centres;
}

double AxisStraightness(const Eigen::VectorXd& y, const Eigen::Matrix2Xd& centres) {
  const long m = y.size();
  if (centres.cols() != m) throw std::invalid_argument("axis straightness: size mismatch");
  if (m < 3) return 0.0;
  const auto [yc, yh] = AxialScale(y);
  const Eigen::Vector2d mean = centres.rowwise().mean();
  const double scale = (centres.colwise() - mean).colwise().norm().maxCoeff();
  if (scale == 0.0) return 0.0;
  // Least-squares line, a candidate axis and the fallback.
  Eigen::MatrixXd X(m, 2);
  X.col(0).setOnes();
  X.col(1) = (y.array() - yc) / yh;
  const Eigen::MatrixXd fit = X.colPivHouseholderQr().solve(centres.transpose());  // 2 x 2
  const Eigen::Vector2d ls_t = fit.row(1).transpose() / yh;
  const Eigen::Vector2d ls_p0 = fit.row(0).transpose() - ls_t * yc;
  double best = MaxDistance(y, centres, ls_p0, ls_t);
  // Minimum enclosing cylinder, a convex (second-order cone) program, solved by cutting planes:
  // each point's circle constraint |p_i - axis(y_i)| <= r is replaced by tangent half-planes
  // (initially 4 directions, then one more per point at its current direction from the axis)
  // and the resulting linear program in (x0, bx, z0, bz, r), in units of `scale` about the
  // centroid, solved exactly. Its optimum is a lower bound of the minimum radius; the largest
  // distance from its axis an upper bound; iterate until they agree to 1e-9. The first cuts only
  // start the iteration (the bounds hold whatever they are): 4 take 14-17 rounds on the shipped
  // parts in a third fewer instructions than 16 (smaller programs each round).
  constexpr int kInitialDirections = 4;
  std::vector<Eigen::Matrix<double, 1, 5>> rows;
  std::vector<double> rhs_list;
  Eigen::Matrix2Xd p(2, m);
  Eigen::VectorXd u(m);
  for (long i = 0; i < m; ++i) {
    u(i) = (y(i) - yc) / yh;
    p.col(i) = (centres.col(i) - mean) / scale;
  }
  auto add_cut = [&](long i, double phi) {
    const double cs = std::cos(phi), sn = std::sin(phi);
    Eigen::Matrix<double, 1, 5> row;
    row << -cs, -cs * u(i), -sn, -sn * u(i), -1.0;
    rows.push_back(row);
    rhs_list.push_back(-(p(0, i) * cs + p(1, i) * sn));
  };
  for (long i = 0; i < m; ++i)
    for (int q = 0; q < kInitialDirections; ++q)
      add_cut(i, 2.0 * std::numbers::pi * q / kInitialDirections);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(5);
  c(4) = 1.0;
  // Each round's program is the last one's with its cuts added: it starts from the last optimum's
  // basis (a few pivots a round instead of a whole solve, 14-17 rounds a part).
  std::vector<int> basis;
  for (int round = 0; round < 40; ++round) {
    Eigen::MatrixXd A(rows.size(), 5);
    Eigen::VectorXd rhs(rows.size());
    for (size_t k = 0; k < rows.size(); ++k) {
      A.row(k) = rows[k];
      rhs(k) = rhs_list[k];
    }
    const LinearProgramResult lp = MinimiseLinearProgram(c, A, rhs, &basis);
    const Eigen::Vector2d t(lp.x(1) * scale / yh, lp.x(3) * scale / yh);
    const Eigen::Vector2d p0 = mean + Eigen::Vector2d(lp.x(0), lp.x(2)) * scale - t * yc;
    best = std::min(best, MaxDistance(y, centres, p0, t));
    double upper = 0.0;
    std::vector<std::pair<long, double>> cuts;
    for (long i = 0; i < m; ++i) {
      const Eigen::Vector2d d(p(0, i) - lp.x(0) - lp.x(1) * u(i),
                              p(1, i) - lp.x(2) - lp.x(3) * u(i));
      const double dist = d.norm();
      upper = std::max(upper, dist);
      if (dist > lp.x(4) * (1.0 + 1e-12)) cuts.emplace_back(i, std::atan2(d.y(), d.x()));
    }
    if (upper - lp.x(4) <= 1e-9 * upper || cuts.empty()) break;
    for (const auto& [i, phi] : cuts) add_cut(i, phi);
  }
  return 2.0 * best;
}

double ProfileStraightness(const Eigen::Matrix2Xd& points) {
  const long n = points.cols();
  if (n < 3) return 0.0;
  std::vector<Eigen::Vector2d> p(n);
  for (long i = 0; i < n; ++i) p[i] = points.col(i);
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  // Andrew's monotone chain.
  std::vector<Eigen::Vector2d> hull(2 * n);
  long k = 0;
  for (long i = 0; i < n; ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (long i = n - 2, t = k + 1; i >= 0; --i) {
    while (k >= t && Cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  hull.resize(std::max<long>(k - 1, 1));
  const long h = static_cast<long>(hull.size());
  if (h < 3) return 0.0;  // collinear
  // The minimum-width strip has one side on a hull edge: for each edge, the farthest vertex.
  double best = std::numeric_limits<double>::infinity();
  for (long e = 0; e < h; ++e) {
    const Eigen::Vector2d& a = hull[e];
    const Eigen::Vector2d& b = hull[(e + 1) % h];
    const double len = (b - a).norm();
    if (len == 0.0) continue;
    double far = 0.0;
    for (long v = 0; v < h; ++v) far = std::max(far, std::abs(Cross(a, b, hull[v])) / len);
    best = std::min(best, far);
  }
  return best;
}

SizeRange TwoPointSizes(const CylinderSamples& s) {
  CheckSamples(s);
  const long n = s.theta.size();
  if (n % 2 != 0) throw std::invalid_argument("two-point sizes need an even number of columns");
  const long half = n / 2;
  for (long j = 0; j < half; ++j) {
    const double diff =
        std::remainder(s.theta(j + half) - s.theta(j) - std::numbers::pi, 2.0 * std::numbers::pi);
    if (std::abs(diff) > 1e-9) {
      throw std::invalid_argument("two-point sizes need diametrically opposite columns");
    }
  }
  SizeRange out{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (long i = 0; i < s.y.size(); ++i) {
    for (long j = 0; j < half; ++j) {
      const double d = s.deviation(i, j) + s.deviation(i, j + half);
      out.min = std::min(out.min, d);
      out.max = std::max(out.max, d);
    }
  }
  return out;
}

CylinderSamples SamplesFromGrid(double nominal_radius, const SurfaceGrid& grid,
                                const Eigen::VectorXd& deviation) {
  if (deviation.size() != grid.size() || grid.row_position.size() != grid.rows ||
      grid.column_angle.size() != grid.columns) {
    throw std::invalid_argument("skin model shape: grid and variation sizes disagree");
  }
  CylinderSamples s;
  s.nominal_radius = nominal_radius;
  s.y = grid.row_position;
  s.theta = grid.column_angle;
  s.deviation.resize(grid.rows, grid.columns);
  for (int i = 0; i < grid.rows; ++i)
    for (int j = 0; j < grid.columns; ++j) s.deviation(i, j) = deviation(grid.index(i, j));
  return s;
}

double EvaluateCylinderForm(FormCharacteristic characteristic, const CylinderSamples& s) {
  switch (characteristic) {
    case FormCharacteristic::kRoundness: {
      if (s.theta.size() < 4) return 0.0;
      double worst = 0.0;
      const Eigen::Matrix2Xd directions = s.Directions();
      for (long i = 0; i < s.y.size(); ++i) {
        worst = std::max(
            worst, MinimumZoneRoundness(s.SectionPoints(static_cast<int>(i), directions)).value);
      }
      return worst;
    }
    case FormCharacteristic::kGeneratrixStraightness: {
      double worst = 0.0;
      Eigen::Matrix2Xd profile(2, s.y.size());
      profile.row(0) = s.y.transpose();
      for (long j = 0; j < s.theta.size(); ++j) {
        profile.row(1) = s.deviation.col(j).transpose();
        worst = std::max(worst, ProfileStraightness(profile));
      }
      return worst;
    }
    case FormCharacteristic::kAxisStraightness:
      if (s.theta.size() < 3) return 0.0;
      return AxisStraightness(s.y, SectionCentres(s));
    case FormCharacteristic::kCylindricity:
      return MinimumZoneCylindricity(s).value;
    default:
      throw std::invalid_argument("a cylinder has no characteristic '" + ToString(characteristic) +
                                  "'");
  }
}

}  // namespace fitfeel::metrology
