#include "framework/model/axial_breathing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/core/simd_clones.h"

namespace fitfeel {
namespace {

// Axial elements per row: at least two (a row's mean displacement then averages a curved profile,
// not one linear piece), and none longer than the loaded face's radius over kRadiusOverElement
// (where the load's edge concentrates the strain, the length that matters is the part's own).
constexpr int kFewestElementsPerRow = 2;
constexpr double kRadiusOverElement = 40.0;
// Growth of the radial layers away from the loaded face, where the load's edges concentrate the
// strain; the tests measure what the mesh leaves (AxialBreathing.ConvergesUnderRefinement, and
// every axisymmetric CalculiX case within 0.15 %).
constexpr double kLayerGrowth = 1.25;
// At least this many layers through a wall: a thin hub carries its load by bending across it.
constexpr int kFewestLayers = 4;

// y[0, n) -= a x[0, n): the band solves' row operation, over every right-hand side at once.
FITFEEL_SIMD_CLONES void SubtractScaled(double* __restrict y, const double* __restrict x, double a,
                                        int n) {
  FITFEEL_NO_FP_CONTRACT
  for (int j = 0; j < n; ++j) y[j] -= a * x[j];
}

// Radial stations from the loaded face into the body, first layer `first` thick.
std::vector<double> RadialStations(const BreathingBody& body, double first) {
  const double wall = body.outer_radius - body.inner_radius;
  double step = std::min(first, wall / kFewestLayers);
  std::vector<double> depth{0.0};
  while (depth.back() + step < wall) {
    depth.push_back(depth.back() + step);
    step *= kLayerGrowth;
  }
  // A last layer thinner than half the one before it is merged into that one.
  if (depth.size() > 1 && wall - depth.back() < 0.5 * (depth.back() - depth[depth.size() - 2])) {
    depth.pop_back();
  }
  depth.push_back(wall);
  std::vector<double> r(depth.size());
  for (std::size_t i = 0; i < depth.size(); ++i) {
    r[i] = body.loaded_inside ? body.inner_radius + depth[i]
                              : body.outer_radius - depth[depth.size() - 1 - i];
  }
  return r;  // increasing
}

// The axisymmetric bilinear element's stiffness per radian (u_r, u_z at its four corners,
// counterclockwise from (r0, z0)), 2 x 2 Gauss points. Strains (e_r, e_z, e_theta, g_rz).
Eigen::Matrix<double, 8, 8> ElementStiffness(double r0, double r1, double z0, double z1,
                                             const Eigen::Matrix4d& d) {
  Eigen::Matrix<double, 8, 8> k = Eigen::Matrix<double, 8, 8>::Zero();
  const double g = 1.0 / std::sqrt(3.0);
  const double hr = 0.5 * (r1 - r0), hz = 0.5 * (z1 - z0);
  const std::array<double, 4> xi{-1.0, 1.0, 1.0, -1.0}, eta{-1.0, -1.0, 1.0, 1.0};
  for (double a : {-g, g}) {
    for (double b : {-g, g}) {
      const double r = r0 + hr * (1.0 + a);
      Eigen::Matrix<double, 4, 8> bm = Eigen::Matrix<double, 4, 8>::Zero();
      for (int n = 0; n < 4; ++n) {
        const double shape = 0.25 * (1.0 + xi[n] * a) * (1.0 + eta[n] * b);
        const double dr = 0.25 * xi[n] * (1.0 + eta[n] * b) / hr;
        const double dz = 0.25 * eta[n] * (1.0 + xi[n] * a) / hz;
        bm(0, 2 * n) = dr;
        bm(1, 2 * n + 1) = dz;
        bm(2, 2 * n) = shape / r;
        bm(3, 2 * n) = dz;
        bm(3, 2 * n + 1) = dr;
      }
      k += bm.transpose() * d * bm * (r * hr * hz);
    }
  }
  return k;
}

// A symmetric positive definite band matrix of half-bandwidth w, factored in place: K = L L'. The
// elements' numbering (radial index fastest) keeps the band two radial stations wide, and a band
// factor has no fill outside it: N w^2 / 2 operations, no reordering.
class BandCholesky {
 public:
  BandCholesky(int n, int w) : n_(n), w_(w), band_(static_cast<std::size_t>(n) * (w + 1), 0.0) {}
  // Row i, column j <= i, j >= i - w.
  double& at(int i, int j) { return band_[static_cast<std::size_t>(i) * (w_ + 1) + (j - i + w_)]; }
  // Factors in place (Cholesky-Banachiewicz, row by row); false if a pivot is not positive.
  bool Factor() {
    for (int i = 0; i < n_; ++i) {
      for (int j = std::max(0, i - w_); j <= i; ++j) {
        double sum = at(i, j);
        for (int k = std::max(0, i - w_); k < j; ++k) {
          sum -= at(i, k) * at(j, k);
        }
        if (j == i) {
          if (!(sum > 0.0)) return false;
          at(i, i) = std::sqrt(sum);
        } else {
          at(i, j) = sum / at(j, j);
        }
      }
    }
    return true;
  }
  // X <- L^-T L^-1 X = K^-1 X for the columns of a row-major X (n rows, `cols` columns): row
  // operations, which run over every right-hand side at once (contiguous, vectorised) instead of
  // one band solve each. Column j is zero above row first[j] (nondecreasing in j): the forward
  // pass skips the columns that are still zero.
  void Solve(double* x, int cols, const std::vector<int>& first) {
    int live = 0;  // columns with first <= i
    for (int i = 0; i < n_; ++i) {
      while (live < cols && first[static_cast<std::size_t>(live)] <= i) ++live;
      double* xi = x + static_cast<std::size_t>(i) * cols;
      for (int k = std::max(0, i - w_); k < i; ++k) {
        SubtractScaled(xi, x + static_cast<std::size_t>(k) * cols, at(i, k), live);
      }
      const double d = at(i, i);
      for (int j = 0; j < live; ++j) xi[j] /= d;
    }
    for (int i = n_ - 1; i >= 0; --i) {
      double* xi = x + static_cast<std::size_t>(i) * cols;
      const double d = at(i, i);
      for (int j = 0; j < cols; ++j) xi[j] /= d;
      for (int k = std::max(0, i - w_); k < i; ++k) {
        SubtractScaled(x + static_cast<std::size_t>(k) * cols, xi, at(i, k), cols);
      }
    }
  }

 private:
  int n_, w_;
  std::vector<double> band_;
};

}  // namespace

AxialBreathing::AxialBreathing(const BreathingBody& body, std::span<const double> row_edges) {
  if (!(body.inner_radius >= 0.0) || !(body.outer_radius > body.inner_radius)) {
    throw UserError("axial breathing needs 0 <= inner radius < outer radius");
  }
  if (body.loaded_inside && !(body.inner_radius > 0.0)) {
    throw UserError("axial breathing: a part loaded on its bore needs a bore (inner radius > 0)");
  }
  const double e = body.material.youngs_modulus, nu = body.material.poisson;
  if (!(e > 0.0) || !(nu > -1.0) || !(nu < 0.5)) {
    throw UserError("axial breathing needs the part's Young's modulus and Poisson's ratio");
  }
  const int rows = static_cast<int>(row_edges.size()) - 1;
  if (rows < 1 || rows > kMostRows) {
    throw UserError("axial breathing needs 1 to " + std::to_string(kMostRows) + " rows, got " +
                    std::to_string(std::max(rows, 0)));
  }
  for (int i = 0; i < rows; ++i) {
    if (!(row_edges[i + 1] > row_edges[i]) || !std::isfinite(row_edges[i + 1] - row_edges[i])) {
      throw UserError("axial breathing needs increasing row edges");
    }
  }

  // Stations: `per_row` equal elements per row along z; layers in r.
  double longest = 0.0;
  for (int i = 0; i < rows; ++i) longest = std::max(longest, row_edges[i + 1] - row_edges[i]);
  const double face_radius = body.loaded_inside ? body.inner_radius : body.outer_radius;
  const int per_row =
      std::max(kFewestElementsPerRow,
               static_cast<int>(std::ceil(longest * kRadiusOverElement / face_radius - 1e-9)));
  std::vector<double> z;
  for (int i = 0; i < rows; ++i) {
    for (int s = 0; s < per_row; ++s) {
      z.push_back(row_edges[i] + (row_edges[i + 1] - row_edges[i]) * s / per_row);
    }
  }
  z.push_back(row_edges[rows]);
  const double mean_element = (row_edges[rows] - row_edges[0]) / (rows * per_row);
  const std::vector<double> r = RadialStations(body, mean_element);
  const int nr = static_cast<int>(r.size()), nz = static_cast<int>(z.size());
  const int loaded = body.loaded_inside ? 0 : nr - 1;  // radial station of the loaded face
  // Radial index fastest: the band of the stiffness is two stations wide.
  auto node = [nr](int iz, int ir) { return iz * nr + ir; };

  // Degrees of freedom, -1 where held.
  std::vector<int> dof(static_cast<std::size_t>(2 * nr * nz), 0);
  for (int iz = 0; iz < nz; ++iz) {
    if (body.inner_radius == 0.0) dof[2 * node(iz, 0)] = -1;  // the axis stays on it
    if (body.held_faces && (iz == 0 || iz == nz - 1)) {
      for (int ir = 0; ir < nr; ++ir) dof[2 * node(iz, ir) + 1] = -1;
    }
  }
  // Free faces: radial loads carry no net axial force; one node fixes the axial translation.
  if (!body.held_faces) dof[2 * node(0, loaded) + 1] = -1;
  int free = 0;
  for (int& d : dof) d = d < 0 ? -1 : free++;

  Eigen::Matrix4d d;
  const double c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
  d << 1.0 - nu, nu, nu, 0.0,  //
      nu, 1.0 - nu, nu, 0.0,   //
      nu, nu, 1.0 - nu, 0.0,   //
      0.0, 0.0, 0.0, 0.5 - nu;
  d *= c;
  // Half-bandwidth: the largest distance between two coupled free unknowns.
  int w = 0;
  for (int iz = 0; iz + 1 < nz; ++iz) {
    for (int ir = 0; ir + 1 < nr; ++ir) {
      int lo = free, hi = -1;
      for (int corner : {node(iz, ir), node(iz, ir + 1), node(iz + 1, ir + 1), node(iz + 1, ir)}) {
        for (int a = 0; a < 2; ++a) {
          if (const int p = dof[2 * corner + a]; p >= 0) {
            lo = std::min(lo, p);
            hi = std::max(hi, p);
          }
        }
      }
      w = std::max(w, hi - lo);
    }
  }
  BandCholesky k(free, w);
  // An element's stiffness depends on its radii and its length only: one per layer while the
  // length stays (equal rows: one per layer for the whole part).
  std::vector<Eigen::Matrix<double, 8, 8>> layer(static_cast<std::size_t>(nr - 1));
  double layer_length = -1.0;
  for (int iz = 0; iz + 1 < nz; ++iz) {
    if (z[iz + 1] - z[iz] != layer_length) {
      layer_length = z[iz + 1] - z[iz];
      for (int ir = 0; ir + 1 < nr; ++ir) {
        layer[static_cast<std::size_t>(ir)] =
            ElementStiffness(r[ir], r[ir + 1], 0.0, layer_length, d);
      }
    }
    for (int ir = 0; ir + 1 < nr; ++ir) {
      const Eigen::Matrix<double, 8, 8>& ke = layer[static_cast<std::size_t>(ir)];
      const std::array<int, 4> corner{node(iz, ir), node(iz, ir + 1), node(iz + 1, ir + 1),
                                      node(iz + 1, ir)};
      for (int a = 0; a < 8; ++a) {
        const int p = dof[2 * corner[a / 2] + a % 2];
        if (p < 0) continue;
        for (int b = 0; b < 8; ++b) {
          const int q = dof[2 * corner[b / 2] + b % 2];
          if (q >= 0 && q <= p) k.at(p, q) += ke(a, b);
        }
      }
    }
  }
  if (!k.Factor()) {
    throw UserError("axial breathing: the part's stiffness is not positive definite");
  }

  // Row j's unit pressure, per radian, is R le / 2 on each end of each element of the loaded face,
  // pushing the face away from the other part; the same weights over the row's length average
  // the face's radial displacement: load_j = R length_j mean_j. So F = mean' K^-1 load, and
  // mean' reads a row's few face nodes.
  const double face = r[loaded];
  const double open = body.loaded_inside ? 1.0 : -1.0;  // outwards opens a bore, inwards a shaft
  std::vector<std::vector<std::pair<int, double>>> mean(static_cast<std::size_t>(rows));
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> u =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>::Zero(free, rows);
  std::vector<int> first(static_cast<std::size_t>(rows), free);
  for (int i = 0; i < rows; ++i) {
    const double length = row_edges[i + 1] - row_edges[i];
    for (int s = 0; s < per_row; ++s) {
      const int iz = i * per_row + s;
      const double le = z[iz + 1] - z[iz];
      for (int end : {iz, iz + 1}) {
        const int p = dof[2 * node(end, loaded)];
        FITFEEL_DEMAND(p >= 0);  // the loaded face's radial motion is never held
        mean[static_cast<std::size_t>(i)].emplace_back(p, open * 0.5 * le / length);
        u(p, i) += open * face * 0.5 * le;
        first[static_cast<std::size_t>(i)] = std::min(first[static_cast<std::size_t>(i)], p);
      }
    }
  }
  k.Solve(u.data(), rows, first);
  influence_.setZero(rows, rows);
  for (int i = 0; i < rows; ++i) {
    for (const auto& [p, weight] : mean[static_cast<std::size_t>(i)]) {
      influence_.row(i) += weight * u.row(p);
    }
  }
  extra_ = influence_;
  extra_.diagonal() -= influence_.rowwise().sum();
}

void AxialBreathing::ExtraDisplacement(const double* mean_pressure, double* out) const {
  Eigen::Map<Eigen::VectorXd>(out, extra_.rows()) =
      extra_ * Eigen::Map<const Eigen::VectorXd>(mean_pressure, extra_.cols());
}

}  // namespace fitfeel
