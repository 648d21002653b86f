#include "framework/model/axial_coupling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <list>
#include <mutex>
#include <string>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/core/simd_clones.h"
#include "framework/model/harmonic_compliance.h"

namespace fitfeel {
namespace {

// Axial elements per row: at least two (a row's mean displacement then averages a curved profile,
// not one linear piece), and none longer than the loaded face's radius over kRadiusOverElement
// (where the load's edge concentrates the strain, the length that matters is the part's own).
constexpr int kFewestElementsPerRow = 2;
constexpr double kRadiusOverElement = 40.0;
// Growth of the radial layers away from the loaded face, where the load's edges concentrate the
// strain; the tests measure what the mesh leaves (AxialCoupling.ConvergesUnderRefinement, and
// every axisymmetric CalculiX case within 0.15 %).
constexpr double kLayerGrowth = 1.25;
// At least this many layers through a wall: a thin hub carries its load by bending across it.
constexpr int kFewestLayers = 4;

// y[0, n) -= sum over t < terms of c[t] x_t[0, n), x_t = x + t * stride, subtracted in the order
// of t: a band solve's step for one row over every right-hand side at once, in one call (a call
// per term was a third of the elements' cost on the shipped parts).
FITFEEL_SIMD_CLONES void SubtractCombination(double* __restrict y, const double* __restrict x,
                                             std::ptrdiff_t stride, const double* __restrict c,
                                             int terms, int n) {
  FITFEEL_NO_FP_CONTRACT
  for (int t = 0; t < terms; ++t) {
    const double* __restrict xt = x + t * stride;
    const double a = c[t];
    for (int j = 0; j < n; ++j) y[j] -= a * xt[j];
  }
}

// A band factor's trailing update for one pivot: row r of `rows` (r < count; row r starts r *
// stride further on, the band's rows one column further right each) loses c[r] c[j] at columns
// j <= r. Each entry subtracts its pivots' products in pivot order (no contraction), so every
// instruction set gives the same factor.
FITFEEL_SIMD_CLONES void RankOneUpdate(double* __restrict rows, int stride,
                                       const double* __restrict c, int count) {
  FITFEEL_NO_FP_CONTRACT
  for (int r = 0; r < count; ++r) {
    double* __restrict row = rows + static_cast<std::ptrdiff_t>(r) * stride;
    const double l = c[r];
    for (int j = 0; j <= r; ++j) row[j] -= l * c[j];
  }
}

// Radial stations from the loaded face into the body, first layer `first` thick.
std::vector<double> RadialStations(const AxialBody& body, double first) {
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

// One of the bilinear element's 2 x 2 Gauss points on (r0, r1) x (z0, z1): where it lies, the four
// corners' shape functions and their derivatives there (corners counterclockwise from (r0, z0)),
// and the half-widths that scale its weight r hr hz.
struct GaussPoint {
  double r, z, hr, hz;
  std::array<double, 4> shape, dr, dz;
};

std::array<GaussPoint, 4> GaussPoints(double r0, double r1, double z0, double z1) {
  const double g = 1.0 / std::sqrt(3.0);
  const std::array<double, 4> xi{-1.0, 1.0, 1.0, -1.0}, eta{-1.0, -1.0, 1.0, 1.0};
  std::array<GaussPoint, 4> points{};
  int k = 0;
  for (double a : {-g, g}) {
    for (double b : {-g, g}) {
      GaussPoint& p = points[static_cast<std::size_t>(k++)];
      p.hr = 0.5 * (r1 - r0);
      p.hz = 0.5 * (z1 - z0);
      p.r = r0 + p.hr * (1.0 + a);
      p.z = z0 + p.hz * (1.0 + b);
      for (std::size_t c = 0; c < 4; ++c) {
        p.shape[c] = 0.25 * (1.0 + xi[c] * a) * (1.0 + eta[c] * b);
        p.dr[c] = 0.25 * xi[c] * (1.0 + eta[c] * b) / p.hr;
        p.dz[c] = 0.25 * eta[c] * (1.0 + xi[c] * a) / p.hz;
      }
    }
  }
  return points;
}

// The bilinear ring element's stiffness per pi (2 pi for order 0) in the Fourier mode of order n:
// u_r = U cos(n theta), u_theta = V sin(n theta), u_z = W cos(n theta) at its four corners,
// counterclockwise from (r0, z0), (U, W) per corner for n = 0 and (U, V, W) otherwise; 2 x 2 Gauss
// points. Strains (e_r, e_z, e_theta, g_rz, g_rtheta, g_thetaz); each is one trigonometric factor
// times a function of (r, z), and the products' factors integrate to the same pi, so the mode's
// energy is that of a 2-D problem in (r, z).
Eigen::MatrixXd ElementStiffness(double r0, double r1, double z0, double z1,
                                 const Eigen::Matrix<double, 6, 6>& d, int order) {
  const int per_node = order == 0 ? 2 : 3;
  const int size = 4 * per_node;
  const int strains = order == 0 ? 4 : 6;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(size, size);
  const double n = order;
  const int w_at = per_node - 1;  // W's place in a corner's unknowns
  for (const GaussPoint& p : GaussPoints(r0, r1, z0, z1)) {
    const double r = p.r;
    Eigen::MatrixXd bm = Eigen::MatrixXd::Zero(strains, size);
    for (int c = 0; c < 4; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      const double shape = p.shape[cc], dr = p.dr[cc], dz = p.dz[cc];
      const int u = per_node * c, w = u + w_at;
      bm(0, u) = dr;
      bm(1, w) = dz;
      bm(2, u) = shape / r;
      bm(3, u) = dz;
      bm(3, w) = dr;
      if (order > 0) {
        const int v = u + 1;
        bm(2, v) = n * shape / r;
        bm(4, u) = -n * shape / r;
        bm(4, v) = dr - shape / r;
        bm(5, v) = dz;
        bm(5, w) = -n * shape / r;
      }
    }
    k += bm.transpose() * d.topLeftCorner(strains, strains) * bm * (r * p.hr * p.hz);
  }
  return k;
}

// A symmetric positive definite band matrix of half-bandwidth w, factored in place: K = L L'. The
// elements' numbering (radial index fastest) keeps the band two radial stations wide, and a band
// factor has no fill outside it: N w^2 / 2 operations, no reordering.
class BandCholesky {
 public:
  // The band lives in `storage` (zeroed here), which the caller keeps.
  BandCholesky(int n, int w, std::vector<double>* storage) : n_(n), w_(w), band_(*storage) {
    band_.assign(static_cast<std::size_t>(n) * (w + 1), 0.0);
  }
  // Row i, column j <= i, j >= i - w.
  double& at(int i, int j) { return band_[static_cast<std::size_t>(i) * (w_ + 1) + (j - i + w_)]; }
  // Factors in place (right-looking: each pivot's column scaled, then the trailing band's rank-one
  // update); false if a pivot is not positive. A row-by-row factor makes every entry wait for the
  // inner product of the one before it in the row (latency-bound: a third of the elements' cost
  // on the shipped parts); the rank-one update has no such chain, its rows run vectorised.
  bool Factor() {
    std::vector<double> column(static_cast<std::size_t>(w_));
    for (int k = 0; k < n_; ++k) {
      const double pivot = at(k, k);
      if (!(pivot > 0.0)) return false;
      at(k, k) = std::sqrt(pivot);
      const double inverse = 1.0 / at(k, k);
      const int below = std::min(w_, n_ - 1 - k);
      for (int r = 0; r < below; ++r) {
        double& l = at(k + 1 + r, k);
        l *= inverse;
        column[static_cast<std::size_t>(r)] = l;
      }
      if (below > 0) RankOneUpdate(&at(k + 1, k + 1), w_, column.data(), below);
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
      const int lo = std::max(0, i - w_);
      // Row i of L holds columns lo .. i - 1 contiguously, the rows of X they take are adjacent.
      SubtractCombination(xi, x + static_cast<std::size_t>(lo) * cols, cols, &at(i, lo), i - lo,
                          live);
      const double d = at(i, i);
      for (int j = 0; j < live; ++j) xi[j] /= d;
    }
    // Backwards, row i takes column i of L below the diagonal (strided in the band: gathered).
    std::vector<double> below(static_cast<std::size_t>(w_));
    for (int i = n_ - 1; i >= 0; --i) {
      double* xi = x + static_cast<std::size_t>(i) * cols;
      const int count = std::min(w_, n_ - 1 - i);
      for (int t = 0; t < count; ++t) below[static_cast<std::size_t>(t)] = at(i + 1 + t, i);
      SubtractCombination(xi, xi + cols, cols, below.data(), count, cols);
      const double d = at(i, i);
      for (int j = 0; j < cols; ++j) xi[j] /= d;
    }
  }

 private:
  int n_, w_;
  std::vector<double>& band_;
};

// The element solves' two large buffers (the band and the loads' right-hand sides, megabytes
// each), kept by each thread from one solve to the next instead of handed back to the kernel and
// faulted in again, zeroed, for each of a scene's fourteen solves (with two threads faulting at
// once, their page faults also wait on each other). Up to kKeptBytes each; a larger one is handed
// back after its solve.
struct ElementBuffers {
  std::vector<double> band, loads;
  static constexpr std::size_t kKeptBytes = std::size_t{32} << 20;
  void Trim() {
    for (std::vector<double>* b : {&band, &loads}) {
      if (b->capacity() * sizeof(double) > kKeptBytes) std::vector<double>().swap(*b);
    }
  }
};

}  // namespace

AxialCoupling::AxialCoupling(const AxialBody& body, std::span<const double> row_edges, int order)
    : order_(order) {
  if (order < 0 || order > kHighestOrder) {
    throw UserError("axial coupling is defined for orders 0 to " + std::to_string(kHighestOrder) +
                    ", not " + std::to_string(order));
  }
  if (!(body.inner_radius >= 0.0) || !(body.outer_radius > body.inner_radius)) {
    throw UserError("axial coupling needs 0 <= inner radius < outer radius");
  }
  if (body.loaded_inside && !(body.inner_radius > 0.0)) {
    throw UserError("axial coupling: a part loaded on its bore needs a bore (inner radius > 0)");
  }
  const double e = body.material.youngs_modulus, nu = body.material.poisson;
  if (!(e > 0.0) || !(nu > -1.0) || !(nu < 0.5)) {
    throw UserError("axial coupling needs the part's Young's modulus and Poisson's ratio");
  }
  const int rows = static_cast<int>(row_edges.size()) - 1;
  if (rows < 1 || rows > kMostRows) {
    throw UserError("axial coupling needs 1 to " + std::to_string(kMostRows) + " rows, got " +
                    std::to_string(std::max(rows, 0)));
  }
  for (int i = 0; i < rows; ++i) {
    if (!(row_edges[i + 1] > row_edges[i]) || !std::isfinite(row_edges[i + 1] - row_edges[i])) {
      throw UserError("axial coupling needs increasing row edges");
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

  // Degrees of freedom, -1 where held: (U, W) per node for order 0, (U, V, W) for the others.
  // kTied: order 1's V on the axis, which is -U there (u_x single-valued).
  constexpr int kTied = -2;
  const int per_node = order == 0 ? 2 : 3, w_at = per_node - 1;
  std::vector<int> dof(static_cast<std::size_t>(per_node * nr * nz), 0);
  for (int iz = 0; iz < nz; ++iz) {
    if (body.inner_radius == 0.0) {
      // The axis stays on it; for orders >= 2 nothing on it moves, for order 1 it moves as a
      // line (W = 0, U + V = 0).
      if (order == 1) {
        dof[per_node * node(iz, 0) + 1] = kTied;
        dof[per_node * node(iz, 0) + w_at] = -1;
      } else {
        for (int a = 0; a < (order == 0 ? 1 : per_node); ++a) {
          dof[per_node * node(iz, 0) + a] = -1;
        }
      }
    }
    if (body.held_faces && (iz == 0 || iz == nz - 1)) {
      for (int ir = 0; ir < nr; ++ir) dof[per_node * node(iz, ir) + w_at] = -1;
    }
  }
  // Free faces: radial loads carry no net axial force; one node fixes the axial translation (the
  // breathing mode's only rigid motion; orders >= 2 have none).
  if (!body.held_faces && order == 0) dof[per_node * node(0, loaded) + w_at] = -1;
  // Order 1's rigid motions, translation (U, V, W) = (1, -1, 0) and rotation (z, -z, -r), are
  // held by U at the face opposite the loaded one at both ends (held faces already stop the
  // rotation: one end). The loads are balanced by body forces (below), so these supports carry
  // nothing and the deformation does not depend on them.
  const int opposite = body.loaded_inside ? nr - 1 : 0;
  if (order == 1) {
    dof[per_node * node(0, opposite)] = -1;
    if (!body.held_faces) dof[per_node * node(nz - 1, opposite)] = -1;
  }
  int free = 0;
  for (int& d : dof) d = d == -1 ? -1 : (d == kTied ? kTied : free++);
  // A node's unknown and its factor: a tied V is U's unknown, negated.
  auto unknown = [&](int entry) -> std::pair<int, double> {
    const int p = dof[static_cast<std::size_t>(entry)];
    if (p == kTied) return {dof[static_cast<std::size_t>(entry - 1)], -1.0};
    return {p, 1.0};
  };

  // Isotropic elasticity on (e_r, e_z, e_theta, g_rz, g_rtheta, g_thetaz).
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(nu);
  d.diagonal().head<3>().setConstant(1.0 - nu);
  d.diagonal().tail<3>().setConstant(0.5 - nu);
  d *= e / ((1.0 + nu) * (1.0 - 2.0 * nu));
  // Half-bandwidth: the largest distance between two coupled free unknowns.
  int w = 0;
  for (int iz = 0; iz + 1 < nz; ++iz) {
    for (int ir = 0; ir + 1 < nr; ++ir) {
      int lo = free, hi = -1;
      for (int corner : {node(iz, ir), node(iz, ir + 1), node(iz + 1, ir + 1), node(iz + 1, ir)}) {
        for (int a = 0; a < per_node; ++a) {
          if (const int p = unknown(per_node * corner + a).first; p >= 0) {
            lo = std::min(lo, p);
            hi = std::max(hi, p);
          }
        }
      }
      w = std::max(w, hi - lo);
    }
  }
  thread_local ElementBuffers buffers;
  struct TrimOnExit {
    ElementBuffers& buffers;
    ~TrimOnExit() { buffers.Trim(); }
  } trim{buffers};
  BandCholesky k(free, w, &buffers.band);
  // An element's stiffness depends on its radii and its length only: one per layer while the
  // length stays (equal rows: one per layer for the whole part).
  std::vector<Eigen::MatrixXd> layer(static_cast<std::size_t>(nr - 1));
  double layer_length = -1.0;
  for (int iz = 0; iz + 1 < nz; ++iz) {
    // Rows of one length differ by rounding: a relative 1e-12 is the same element.
    if (std::abs(z[iz + 1] - z[iz] - layer_length) > 1e-12 * layer_length) {
      layer_length = z[iz + 1] - z[iz];
      for (int ir = 0; ir + 1 < nr; ++ir) {
        layer[static_cast<std::size_t>(ir)] =
            ElementStiffness(r[ir], r[ir + 1], 0.0, layer_length, d, order);
      }
    }
    for (int ir = 0; ir + 1 < nr; ++ir) {
      const Eigen::MatrixXd& ke = layer[static_cast<std::size_t>(ir)];
      const std::array<int, 4> corner{node(iz, ir), node(iz, ir + 1), node(iz + 1, ir + 1),
                                      node(iz + 1, ir)};
      const int size = 4 * per_node;
      std::array<std::pair<int, double>, 12> unknowns;
      for (int a = 0; a < size; ++a) {
        unknowns[static_cast<std::size_t>(a)] =
            unknown(per_node * corner[a / per_node] + a % per_node);
      }
      for (int a = 0; a < size; ++a) {
        const auto [p, fa] = unknowns[static_cast<std::size_t>(a)];
        if (p < 0) continue;
        for (int b = 0; b < size; ++b) {
          const auto [q, fb] = unknowns[static_cast<std::size_t>(b)];
          // A tied pair adds its coupling to both triangles of the one unknown.
          if (q >= 0 && q <= p) k.at(p, q) += fa * fb * ke(a, b);
        }
      }
    }
  }
  if (!k.Factor()) {
    throw UserError("axial coupling: the part's stiffness is not positive definite");
  }

  // Row j's unit pressure (per radian for order 0, per pi for the others, as the stiffness) is
  // p cos(n theta), R le / 2 on each end of each element of the loaded face, pushing the face away
  // from the other part; the same weights over the row's length average the face's radial
  // displacement: load_j = R length_j mean_j. So F = mean' K^-1 load, and mean' reads a row's few
  // face nodes. (The Gram form R (L^-1 mean)' (L^-1 mean) diag(length) saves the back
  // substitution but costs rows^2 per unknown where the band costs twice its width: more here.)
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const double face = r[loaded];
  const double open = body.loaded_inside ? 1.0 : -1.0;  // outwards opens a bore, inwards a shaft
  std::vector<std::vector<std::pair<int, double>>> mean(static_cast<std::size_t>(rows));
  Eigen::VectorXd length(rows);
  for (int i = 0; i < rows; ++i) length[i] = row_edges[i + 1] - row_edges[i];
  // A part whose rows mirror about its middle is the same body loaded from either end (the
  // elements, the supports' effect and the body loads all mirror): F(i, j) = F(R-1-i, R-1-j), so
  // only the loads of the far half are solved. Their right-hand sides are zero until that half,
  // which the forward pass skips: 2.4 times fewer operations than every row's.
  bool mirrored = rows > 1;
  for (int i = 0; i < rows && mirrored; ++i) {
    mirrored = std::abs(length[i] - length[rows - 1 - i]) <= 1e-12 * length[i];
  }
  const int solved_from = mirrored ? rows / 2 : 0;  // the first row whose load is solved
  const int solved = rows - solved_from;
  buffers.loads.assign(static_cast<std::size_t>(free) * solved, 0.0);
  Eigen::Map<RowMajor> u(buffers.loads.data(), free, solved);
  std::vector<int> first(static_cast<std::size_t>(solved), free);
  for (int i = 0; i < rows; ++i) {
    for (int s = 0; s < per_row; ++s) {
      const int iz = i * per_row + s;
      const double le = z[iz + 1] - z[iz];
      for (int end : {iz, iz + 1}) {
        const int p = dof[per_node * node(end, loaded)];
        FITFEEL_DEMAND(p >= 0);  // the loaded face's radial motion is never held
        mean[static_cast<std::size_t>(i)].emplace_back(p, open * 0.5 * le / length[i]);
        if (i < solved_from) continue;
        const int c = i - solved_from;
        u(p, c) += open * face * 0.5 * le;
        first[static_cast<std::size_t>(c)] = std::min(first[static_cast<std::size_t>(c)], p);
      }
    }
  }
  k.Solve(u.data(), solved, first);
  // The solved loads' columns of F (column c is row solved_from + c's load).
  Eigen::MatrixXd half = Eigen::MatrixXd::Zero(rows, solved);
  for (int i = 0; i < rows; ++i) {
    for (const auto& [p, weight] : mean[static_cast<std::size_t>(i)]) {
      half.row(i) += weight * u.row(p);
    }
  }
  if (order == 1) {
    // A load cos(theta) has a net force and moment, which the rest of the model carries by the
    // part's rigid offset and tilt: here body forces b(z) = alpha + beta z (per unit volume,
    // along x: U-load b, V-load -b) balance each row's (inertia relief), so the supports carry
    // nothing. The two unit body loads once, each row's share by superposition. With them each
    // row's centroid displacement along x, the mean of u_x = U cos^2 - V sin^2 over its volume
    // (integral of (U - V) r dr dz / ((b^2 - a^2) L)): its line is the part's rigid motion.
    RowMajor body_u = RowMajor::Zero(free, 2);
    // centroid_of(i, p): row i's centroid displacement per unknown p.
    Eigen::SparseMatrix<double, Eigen::RowMajor> centroid_of(rows, free);
    std::vector<Eigen::Triplet<double>> entries;
    const double a2 = body.outer_radius * body.outer_radius - body.inner_radius * body.inner_radius;
    for (int iz = 0; iz + 1 < nz; ++iz) {
      const int row = iz / per_row;
      const double volume = a2 * length[row];
      for (int ir = 0; ir + 1 < nr; ++ir) {
        const std::array<int, 4> corner{node(iz, ir), node(iz, ir + 1), node(iz + 1, ir + 1),
                                        node(iz + 1, ir)};
        for (const GaussPoint& g : GaussPoints(r[ir], r[ir + 1], z[iz], z[iz + 1])) {
          for (int c = 0; c < 4; ++c) {
            const double weight = g.shape[static_cast<std::size_t>(c)] * g.r * g.hr * g.hz;
            for (int a = 0; a < 2; ++a) {  // U takes +b, V takes -b
              const auto [p, f] = unknown(per_node * corner[c] + a);
              if (p < 0) continue;
              const double sign = (a == 0 ? 1.0 : -1.0) * f * weight;
              body_u(p, 0) += sign;
              body_u(p, 1) += sign * g.z;
              entries.emplace_back(row, p, sign / volume);
            }
          }
        }
      }
    }
    centroid_of.setFromTriplets(entries.begin(), entries.end());
    k.Solve(body_u.data(), 2, std::vector<int>{0, 0});
    Eigen::MatrixX2d body_mean = Eigen::MatrixX2d::Zero(rows, 2);
    for (int i = 0; i < rows; ++i) {
      for (const auto& [p, weight] : mean[static_cast<std::size_t>(i)]) {
        body_mean.row(i) += weight * body_u.row(p);
      }
    }
    const Eigen::MatrixX2d body_centroid = centroid_of * body_u;
    Eigen::MatrixXd centroid = centroid_of * u;
    // Generalised forces (per pi) on the rigid motions: a body load b integrates to
    // 2 integral of b r dr dz on both; row j's face load to open R L_j and open R L_j z_j.
    const double z0 = row_edges[0], z1 = row_edges[rows];
    const double m0 = a2 * (z1 - z0), m1 = a2 * (z1 * z1 - z0 * z0) / 2.0,
                 m2 = a2 * (z1 * z1 * z1 - z0 * z0 * z0) / 3.0;
    Eigen::Matrix2d balance;
    balance << m0, m1, m1, m2;
    const Eigen::PartialPivLU<Eigen::Matrix2d> lu(balance);
    for (int c = 0; c < solved; ++c) {
      const int j = solved_from + c;
      const double force = open * face * length[j];
      const double centre = 0.5 * (row_edges[j] + row_edges[j + 1]);
      Eigen::Vector2d coef;
      if (body.held_faces) {
        coef << -force / m0, 0.0;  // the held faces carry the moment
      } else {
        coef = lu.solve(Eigen::Vector2d(-force, -force * centre));
      }
      half.col(c) += body_mean * coef;
      centroid.col(c) += body_centroid * coef;
    }
    // The part's rigid motion is its axis's, which the rigid solve owns (and each section's own
    // order-1 compliance is its face relative to its centroid): the least-squares line in z
    // through the rows' centroids (length-weighted; a constant with held faces) is removed. The
    // centroids move along x and F opens the interface: a shaft's face opens as its axis moves
    // the other way (open = -1), so the line is removed with that sign, and a rigid motion,
    // whatever holds the part, leaves F as it was.
    Eigen::MatrixXd basis(rows, body.held_faces ? 1 : 2);
    for (int i = 0; i < rows; ++i) {
      basis(i, 0) = 1.0;
      if (!body.held_faces) basis(i, 1) = 0.5 * (row_edges[i] + row_edges[i + 1]);
    }
    const Eigen::MatrixXd normal = basis.transpose() * length.asDiagonal() * basis;
    half -= open * basis * normal.ldlt().solve(basis.transpose() * length.asDiagonal() * centroid);
  }
  influence_.resize(rows, rows);
  influence_.rightCols(solved) = half;
  for (int j = 0; j < solved_from; ++j) {
    for (int i = 0; i < rows; ++i) influence_(i, j) = influence_(rows - 1 - i, rows - 1 - j);
  }
  extra_ = influence_;
  if (order == 0) {
    extra_.diagonal() -= influence_.rowwise().sum();
  } else {
    // Plane sections are not the 3-D state of a uniform load cos(n theta) (free faces: between
    // plane stress and plane strain, 7 to 10 % stiffer than plane stress in the middle of a part
    // as long as it is wide), so the whole of F counts, less what the sections already have.
    extra_.diagonal().array() -=
        RingHarmonicCompliance(body.inner_radius, body.outer_radius, body.loaded_inside,
                               body.material, body.held_faces, order);
  }
}

namespace {

struct MemoEntry {
  AxialBody body;
  std::vector<double> edges;
  int order;
  AxialCoupling value;
};

struct Memo {
  std::mutex mutex;
  std::list<MemoEntry> entries;  // most recently used first
};

Memo& SharedMemo() {
  static Memo memo;
  return memo;
}

}  // namespace

void AxialCoupling::ForgetShared() {
  Memo& memo = SharedMemo();
  const std::lock_guard<std::mutex> lock(memo.mutex);
  memo.entries.clear();
}

AxialCoupling AxialCoupling::Shared(const AxialBody& body, std::span<const double> row_edges,
                                    int order) {
  Memo& memo = SharedMemo();
  auto same = [&](const MemoEntry& e) {
    return e.order == order && e.body.inner_radius == body.inner_radius &&
           e.body.outer_radius == body.outer_radius && e.body.loaded_inside == body.loaded_inside &&
           e.body.held_faces == body.held_faces &&
           e.body.material.youngs_modulus == body.material.youngs_modulus &&
           e.body.material.poisson == body.material.poisson &&
           std::equal(e.edges.begin(), e.edges.end(), row_edges.begin(), row_edges.end());
  };
  {
    const std::lock_guard<std::mutex> lock(memo.mutex);
    for (auto it = memo.entries.begin(); it != memo.entries.end(); ++it) {
      if (same(*it)) {
        memo.entries.splice(memo.entries.begin(), memo.entries, it);
        return memo.entries.front().value;
      }
    }
  }
  AxialCoupling value(body, row_edges, order);  // outside the lock: other parts go on
  const std::lock_guard<std::mutex> lock(memo.mutex);
  memo.entries.push_front(
      MemoEntry{body, std::vector<double>(row_edges.begin(), row_edges.end()), order, value});
  if (memo.entries.size() > kMemoEntries) memo.entries.pop_back();
  return value;
}

void AxialCoupling::ExtraDisplacement(const double* mean_pressure, double* out) const {
  Eigen::Map<Eigen::VectorXd>(out, extra_.rows()) =
      extra_ * Eigen::Map<const Eigen::VectorXd>(mean_pressure, extra_.cols());
}

}  // namespace fitfeel
