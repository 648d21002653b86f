#include "surfaces/cylindrical/elastic/axial_coupling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "surfaces/cylindrical/elastic/band_cholesky.h"
#include "surfaces/cylindrical/elastic/column_sums.h"
#include "surfaces/cylindrical/elastic/harmonic_compliance.h"

namespace fitfeel::cylindrical {
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

// Order 1's V on the axis, which is -U there (u_x single-valued): the entry takes U's unknown.
constexpr int kTied = -2;

// A part's elements: stations, numbering and the loads' data, shared by both eliminations.
struct ElementMesh {
  const AxialBody* body = nullptr;
  int order = 0, per_node = 0, nr = 0, nz = 0, rows = 0, per_row = 0;
  int loaded = 0;  // radial station of the loaded face
  int free = 0;    // unknowns
  std::vector<double> r, z;
  // Per (station, radial station, component), radial index fastest: the unknown, -1 where held,
  // kTied for a tied V.
  std::vector<int> dof;
  Eigen::Matrix<double, 6, 6> d;
  Eigen::VectorXd length;  // the rows' lengths
  double face = 0.0, open = 0.0;
  int solved_from = 0, solved = 0;  // the loads solved: rows solved_from .. rows - 1

  int node(int iz, int ir) const { return iz * nr + ir; }
  // b^2 - a^2 of the part's outer and inner radii: a row's volume per its length (per pi), and
  // the rigid motions' moments.
  double RadiiSquared() const {
    return body->outer_radius * body->outer_radius - body->inner_radius * body->inner_radius;
  }
  // A node's unknown and its factor: a tied V is U's unknown, negated.
  std::pair<int, double> unknown(int entry) const {
    const int p = dof[static_cast<std::size_t>(entry)];
    if (p == kTied) return {dof[static_cast<std::size_t>(entry - 1)], -1.0};
    return {p, 1.0};
  }
  // Half-bandwidth of the stiffness in a numbering `number(entry) -> (unknown, factor)` over the
  // element columns [from, to).
  template <typename Number>
  int Bandwidth(int from, int to, const Number& number) const {
    int w = 0;
    for (int iz = from; iz < to; ++iz) {
      for (int ir = 0; ir + 1 < nr; ++ir) {
        int lo = std::numeric_limits<int>::max(), hi = -1;
        for (int corner :
             {node(iz, ir), node(iz, ir + 1), node(iz + 1, ir + 1), node(iz + 1, ir)}) {
          for (int a = 0; a < per_node; ++a) {
            if (const int p = number(per_node * corner + a).first; p >= 0) {
              lo = std::min(lo, p);
              hi = std::max(hi, p);
            }
          }
        }
        if (hi >= 0) w = std::max(w, hi - lo);
      }
    }
    return w;
  }
};

// What the ctor needs of K^-1: the rows' mean face displacement under the solved rows' loads
// (`half`, rows x solved) and, for order 1, under the two body loads (`body_mean`), and the rows'
// centroid displacement under both (`centroid`, `body_centroid`).
struct Responses {
  Eigen::MatrixXd half, centroid;
  Eigen::MatrixX2d body_mean, body_centroid;
};

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Adds the element stiffness of the element columns [from, to) into `k` (in the numbering
// `number`, which must keep them in k's band).
template <typename Number>
void Assemble(const ElementMesh& m, int from, int to, const Number& number, BandCholesky* k) {
  // An element's stiffness depends on its radii and its length only: one per layer while the
  // length stays (equal rows: one per layer for the whole part).
  std::vector<Eigen::MatrixXd> layer(static_cast<std::size_t>(m.nr - 1));
  double layer_length = -1.0;
  for (int iz = from; iz < to; ++iz) {
    const double le = m.z[static_cast<std::size_t>(iz) + 1] - m.z[static_cast<std::size_t>(iz)];
    // Rows of one length differ by rounding: a relative 1e-12 is the same element.
    if (std::abs(le - layer_length) > 1e-12 * layer_length) {
      layer_length = le;
      for (int ir = 0; ir + 1 < m.nr; ++ir) {
        layer[static_cast<std::size_t>(ir)] = ElementStiffness(
            m.r[static_cast<std::size_t>(ir)], m.r[static_cast<std::size_t>(ir) + 1], 0.0,
            layer_length, m.d, m.order);
      }
    }
    for (int ir = 0; ir + 1 < m.nr; ++ir) {
      const Eigen::MatrixXd& ke = layer[static_cast<std::size_t>(ir)];
      const std::array<int, 4> corner{m.node(iz, ir), m.node(iz, ir + 1), m.node(iz + 1, ir + 1),
                                      m.node(iz + 1, ir)};
      const int size = 4 * m.per_node;
      std::array<std::pair<int, double>, 12> unknowns;
      for (int a = 0; a < size; ++a) {
        unknowns[static_cast<std::size_t>(a)] =
            number(m.per_node * corner[a / m.per_node] + a % m.per_node);
      }
      for (int a = 0; a < size; ++a) {
        const auto [p, fa] = unknowns[static_cast<std::size_t>(a)];
        if (p < 0) continue;
        for (int b = 0; b < size; ++b) {
          const auto [q, fb] = unknowns[static_cast<std::size_t>(b)];
          // A tied pair adds its coupling to both triangles of the one unknown.
          if (q >= 0 && q <= p) k->at(p, q) += fa * fb * ke(a, b);
        }
      }
    }
  }
}

// Calls add(entry, weight, z) at each Gauss point for order 1's unit body load on the element
// column iz, layer ir (U takes +b, V takes -b; weight per unit b, before the tie's factor), z the
// point's, measured from z0.
template <typename Add>
void BodyLoad(const ElementMesh& m, int iz, int ir, double z0, const Add& add) {
  const std::array<int, 4> corner{m.node(iz, ir), m.node(iz, ir + 1), m.node(iz + 1, ir + 1),
                                  m.node(iz + 1, ir)};
  const auto zi = static_cast<std::size_t>(iz);
  const auto ri = static_cast<std::size_t>(ir);
  for (const GaussPoint& g : GaussPoints(m.r[ri], m.r[ri + 1], m.z[zi] - z0, m.z[zi + 1] - z0)) {
    for (int c = 0; c < 4; ++c) {
      const double weight = g.shape[static_cast<std::size_t>(c)] * g.r * g.hr * g.hz;
      add(m.per_node * corner[static_cast<std::size_t>(c)], weight, g.z);
      add(m.per_node * corner[static_cast<std::size_t>(c)] + 1, -weight, g.z);
    }
  }
}

// The whole part's band, factored, and each solved row's load solved at once.
Responses BandResponses(const ElementMesh& m) {
  const auto number = [&m](int entry) { return m.unknown(entry); };
  const int w = m.Bandwidth(0, m.nz - 1, number);
  std::vector<double> loads;
  BandCholesky k(m.free, w);
  Assemble(m, 0, m.nz - 1, number, &k);
  if (!k.Factor()) {
    throw UserError("axial coupling: the part's stiffness is not positive definite");
  }
  const int rows = m.rows;
  std::vector<std::vector<std::pair<int, double>>> mean(static_cast<std::size_t>(rows));
  loads.assign(static_cast<std::size_t>(m.free) * m.solved, 0.0);
  Eigen::Map<RowMajor> u(loads.data(), m.free, m.solved);
  std::vector<int> first(static_cast<std::size_t>(m.solved), m.free);
  for (int i = 0; i < rows; ++i) {
    for (int s = 0; s < m.per_row; ++s) {
      const int iz = i * m.per_row + s;
      const double le = m.z[static_cast<std::size_t>(iz) + 1] - m.z[static_cast<std::size_t>(iz)];
      for (int end : {iz, iz + 1}) {
        const int p = m.dof[static_cast<std::size_t>(m.per_node * m.node(end, m.loaded))];
        FITFEEL_DEMAND(p >= 0);  // the loaded face's radial motion is never held
        mean[static_cast<std::size_t>(i)].emplace_back(p, m.open * 0.5 * le / m.length[i]);
        if (i < m.solved_from) continue;
        const int c = i - m.solved_from;
        u(p, c) += m.open * m.face * 0.5 * le;
        first[static_cast<std::size_t>(c)] = std::min(first[static_cast<std::size_t>(c)], p);
      }
    }
  }
  k.Solve(u.data(), m.solved, first);
  Responses out;
  out.half = Eigen::MatrixXd::Zero(rows, m.solved);
  for (int i = 0; i < rows; ++i) {
    for (const auto& [p, weight] : mean[static_cast<std::size_t>(i)]) {
      out.half.row(i) += weight * u.row(p);
    }
  }
  if (m.order != 1) return out;
  RowMajor body_u = RowMajor::Zero(m.free, 2);
  // centroid_of(i, p): row i's centroid displacement per unknown p.
  Eigen::SparseMatrix<double, Eigen::RowMajor> centroid_of(rows, m.free);
  std::vector<Eigen::Triplet<double>> entries;
  const double a2 = m.RadiiSquared();
  for (int iz = 0; iz + 1 < m.nz; ++iz) {
    const int row = iz / m.per_row;
    const double volume = a2 * m.length[row];
    for (int ir = 0; ir + 1 < m.nr; ++ir) {
      BodyLoad(m, iz, ir, 0.0, [&](int entry, double weight, double z) {
        const auto [p, f] = m.unknown(entry);
        if (p < 0) return;
        body_u(p, 0) += f * weight;
        body_u(p, 1) += f * weight * z;
        entries.emplace_back(row, p, f * weight / volume);
      });
    }
  }
  centroid_of.setFromTriplets(entries.begin(), entries.end());
  k.Solve(body_u.data(), 2, std::vector<int>{0, 0});
  out.body_mean = Eigen::MatrixX2d::Zero(rows, 2);
  for (int i = 0; i < rows; ++i) {
    for (const auto& [p, weight] : mean[static_cast<std::size_t>(i)]) {
      out.body_mean.row(i) += weight * body_u.row(p);
    }
  }
  out.body_centroid = centroid_of * body_u;
  out.centroid = centroid_of * u;
  return out;
}

// A part whose element columns are all of one length, cut by station lines every `k` rows into
// equal groups: each group's inside is eliminated once for all (its equations are the same in
// every group), which leaves the lines' unknowns, a band twice a line's width but `per_row * k`
// times shorter. What a load or a readout does inside a group is carried by a few patterns per
// group (each row's face weights; for order 1 each row's body weights and the z-weighted ones),
// the same in every group: with C the inside's stiffness, K_ib its coupling to the two lines and
// the lines' stiffness S = K_bb - K_bi C^-1 K_ib, o' K^-1 f = o~' S^-1 f~ + o_i' C^-1 f_i with
// v~ = v_b - K_bi C^-1 v_i (static condensation: the same K^-1 to rounding).
Responses CondensedResponses(const ElementMesh& m, int k) {
  const int s = m.per_row * k;  // element columns per group
  const int groups = m.rows / k;
  const int slots = m.per_node * m.nr;  // entries per station
  // The numbering of an inside station (every station but the two ends has the same held and
  // tied entries): slot -> index within the station, -1 held; a tied V takes U's index, negated.
  std::vector<int> slot_index(static_cast<std::size_t>(slots), -1);
  std::vector<double> slot_sign(static_cast<std::size_t>(slots), 1.0);
  int line = 0;  // unknowns per station
  for (int a = 0; a < slots; ++a) {
    const int p = m.dof[static_cast<std::size_t>(slots + a)];
    if (p == kTied) {
      slot_index[static_cast<std::size_t>(a)] = slot_index[static_cast<std::size_t>(a) - 1];
      slot_sign[static_cast<std::size_t>(a)] = -1.0;
    } else if (p >= 0) {
      slot_index[static_cast<std::size_t>(a)] = line++;
    }
  }
  // Every inside station is numbered so; the two ends only hold more (their supports).
  for (int station = 0; station < m.nz; ++station) {
    const bool end = station == 0 || station == m.nz - 1;
    for (int a = 0; a < slots; ++a) {
      const int p = m.dof[static_cast<std::size_t>(station * slots + a)];
      const int inside = m.dof[static_cast<std::size_t>(slots + a)];
      const bool same = (p == kTied) == (inside == kTied) && (p == -1) == (inside == -1);
      FITFEEL_DEMAND(same || (end && p == -1));
    }
  }
  // The end stations' extra supports, held by pinning their line unknowns.
  std::vector<int> pinned;  // unknowns of the lines' system
  for (int end : {0, groups}) {
    const int station = end * s;
    for (int a = 0; a < slots; ++a) {
      const int g = slot_index[static_cast<std::size_t>(a)];
      if (g >= 0 && slot_sign[static_cast<std::size_t>(a)] > 0.0 &&
          m.dof[static_cast<std::size_t>(station * slots + a)] == -1) {
        pinned.push_back(end * line + g);
      }
    }
  }
  // One group, stations 0 .. s, numbered station by station.
  const auto local = [&](int entry) -> std::pair<int, double> {
    const int station = entry / slots, a = entry % slots;
    const int g = slot_index[static_cast<std::size_t>(a)];
    if (g < 0) return {-1, 0.0};
    return {station * line + g, slot_sign[static_cast<std::size_t>(a)]};
  };
  const int n_local = (s + 1) * line;
  const int w = m.Bandwidth(0, s, local);
  BandCholesky kg(n_local, w);
  Assemble(m, 0, s, local, &kg);
  const auto kv = [&](int i, int j) {
    if (i < j) std::swap(i, j);
    return i - j <= w ? kg.at(i, j) : 0.0;
  };
  // The inside, stations 1 .. s - 1.
  const int ni = (s - 1) * line;
  BandCholesky c(ni, w);
  for (int i = 0; i < ni; ++i) {
    for (int j = std::max(0, i - w); j <= i; ++j) c.at(i, j) = kg.at(i + line, j + line);
  }
  if (!c.Factor()) {
    throw UserError("axial coupling: the part's stiffness is not positive definite");
  }
  // The inside's coupling to the left line (through station 1) and to the right (station s - 1).
  const int last = (s - 2) * line;  // station s - 1's first inside unknown
  Eigen::MatrixXd kl(line, line), kr(line, line);
  for (int b = 0; b < line; ++b) {
    for (int a = 0; a < line; ++a) {
      kl(b, a) = kv(line + b, a);
      kr(b, a) = kv(last + line + b, s * line + a);
    }
  }
  // Every product the lines need is a' C^-1 b = (L^-1 a)' (L^-1 b) with C = L L': forward passes
  // only, the left line's coupling over the whole inside, the right line's over its last station
  // (above which L^-1 of it is zero).
  RowMajor v = RowMajor::Zero(ni, 2 * line);  // L^-1 K_ib: the left line's, then the right's
  v.block(0, 0, line, line) = kl;
  v.block(last, line, line, line) = kr;
  std::vector<int> first(static_cast<std::size_t>(2 * line), 0);
  std::fill(first.begin() + line, first.end(), last);
  c.Forward(v.data(), 2 * line, first);
  const auto v_left = v.leftCols(line);
  const auto v_right = v.block(last, line, line, line);  // its only rows that are not zero
  // The patterns: each row's face weights (the mean's), then for order 1 each row's body weights
  // and the group's z-weighted body weights (z from the group's first station).
  const bool body = m.order == 1;
  const int np = body ? 2 * k + 1 : k;
  RowMajor pattern = RowMajor::Zero(n_local, np);
  for (int row = 0; row < k; ++row) {
    for (int e = 0; e < m.per_row; ++e) {
      const int iz = row * m.per_row + e;
      const double le = m.z[static_cast<std::size_t>(iz) + 1] - m.z[static_cast<std::size_t>(iz)];
      for (int end : {iz, iz + 1}) {
        const auto [p, f] = local(m.per_node * m.node(end, m.loaded));
        FITFEEL_DEMAND(p >= 0);  // the loaded face's radial motion is never held
        pattern(p, row) += f * m.open * 0.5 * le / m.length[row];
      }
      if (!body) continue;
      for (int ir = 0; ir + 1 < m.nr; ++ir) {
        BodyLoad(m, iz, ir, m.z[0], [&](int entry, double weight, double z) {
          const auto [p, f] = local(entry);
          if (p < 0) return;
          pattern(p, k + row) += f * weight;
          pattern(p, 2 * k) += f * weight * z;
        });
      }
    }
  }
  RowMajor y = pattern.middleRows(line, ni);  // L^-1 on the inside's part
  c.Forward(y.data(), np, std::vector<int>(static_cast<std::size_t>(np), 0));
  // The patterns condensed onto the two lines, and what they do inside: o_i' C^-1 f_i.
  Eigen::MatrixXd condensed(2 * line, np);
  condensed.topRows(line) = pattern.topRows(line) - v_left.transpose() * y;
  condensed.bottomRows(line) =
      pattern.bottomRows(line) - v_right.transpose() * y.middleRows(last, line);
  const Eigen::MatrixXd inside = y.transpose() * y;

  // The lines' system: each group's S on its two lines, band 2 lines wide.
  const int n_lines = (groups + 1) * line;
  BandCholesky sg(n_lines, 2 * line - 1, line);
  const Eigen::MatrixXd s_ll = [&] {
    Eigen::MatrixXd a(line, line);
    for (int i = 0; i < line; ++i) {
      for (int j = 0; j < line; ++j) a(i, j) = kv(i, j);
    }
    return Eigen::MatrixXd(a - v_left.transpose() * v_left);
  }();
  const Eigen::MatrixXd s_rr = [&] {
    Eigen::MatrixXd a(line, line);
    for (int i = 0; i < line; ++i) {
      for (int j = 0; j < line; ++j) a(i, j) = kv(s * line + i, s * line + j);
    }
    return Eigen::MatrixXd(a - v_right.transpose() * v_right);
  }();
  const Eigen::MatrixXd s_rl = -v_right.transpose() * v_left.middleRows(last, line);
  for (int g = 0; g < groups; ++g) {
    const int l0 = g * line, r0 = (g + 1) * line;
    for (int i = 0; i < line; ++i) {
      for (int j = 0; j <= i; ++j) {
        sg.at(l0 + i, l0 + j) += s_ll(i, j);
        sg.at(r0 + i, r0 + j) += s_rr(i, j);
      }
      for (int j = 0; j < line; ++j) sg.at(r0 + i, l0 + j) += s_rl(i, j);
    }
  }
  const int band = 2 * line - 1;
  for (int q : pinned) {
    for (int j = std::max(0, q - band); j < q; ++j) sg.at(q, j) = 0.0;
    for (int i = q + 1; i <= std::min(n_lines - 1, q + band); ++i) sg.at(i, q) = 0.0;
    sg.at(q, q) = 1.0;
  }
  if (!sg.Factor()) {
    throw UserError("axial coupling: the part's stiffness is not positive definite");
  }

  // The loads condensed onto the lines, solved at once: the solved rows', then order 1's two
  // body loads (b = 1 and b = z over the whole part).
  const int loads = m.solved + (body ? 2 : 0);
  RowMajor u = RowMajor::Zero(n_lines, loads);
  for (int c0 = 0; c0 < m.solved; ++c0) {
    const int j = m.solved_from + c0, g = j / k;
    u.col(c0).segment(g * line, 2 * line) += m.face * m.length[j] * condensed.col(j % k);
  }
  // Each group's body weights for b = 1, and for b = z its first station's z times them plus its
  // own z-weighted ones (z in the rows' coordinates, as the whole band's).
  const Eigen::VectorXd group_body =
      body ? Eigen::VectorXd(condensed.middleCols(k, k).rowwise().sum()) : Eigen::VectorXd();
  for (int g = 0; body && g < groups; ++g) {
    const double z0 = m.z[static_cast<std::size_t>(g * s)];
    u.col(m.solved).segment(g * line, 2 * line) += group_body;
    u.col(m.solved + 1).segment(g * line, 2 * line) += z0 * group_body + condensed.col(2 * k);
  }
  for (int q : pinned) u.row(q).setZero();
  sg.Solve(u.data(), loads, std::vector<int>(static_cast<std::size_t>(loads), 0));

  // Readouts: each row's mean (and centroid) against every load, plus what both do inside.
  Responses out;
  out.half.resize(m.rows, m.solved);
  const double a2 = m.RadiiSquared();
  if (body) {
    out.centroid.resize(m.rows, m.solved);
    out.body_mean.resize(m.rows, 2);
    out.body_centroid.resize(m.rows, 2);
  }
  const Eigen::VectorXd inside_body =
      body ? Eigen::VectorXd(inside.middleCols(k, k).rowwise().sum()) : Eigen::VectorXd();
  for (int i = 0; i < m.rows; ++i) {
    const int g = i / k, ri = i % k;
    const auto block = u.middleRows(g * line, 2 * line);
    out.half.row(i) = condensed.col(ri).transpose() * block.leftCols(m.solved);
    const double volume = a2 * m.length[i];
    if (body) {
      out.centroid.row(i) = condensed.col(k + ri).transpose() * block.leftCols(m.solved) / volume;
      out.body_mean.row(i) = condensed.col(ri).transpose() * block.rightCols(2);
      out.body_centroid.row(i) = condensed.col(k + ri).transpose() * block.rightCols(2) / volume;
      const double z0 = m.z[static_cast<std::size_t>(g * s)];
      out.body_mean(i, 0) += inside_body[ri];
      out.body_mean(i, 1) += z0 * inside_body[ri] + inside(ri, 2 * k);
      out.body_centroid(i, 0) += inside_body[k + ri] / volume;
      out.body_centroid(i, 1) += (z0 * inside_body[k + ri] + inside(k + ri, 2 * k)) / volume;
    }
    // The loads of the same group's rows.
    for (int j = std::max(g * k, m.solved_from); j < (g + 1) * k; ++j) {
      const double scale = m.face * m.length[j];
      out.half(i, j - m.solved_from) += scale * inside(ri, j % k);
      if (body) out.centroid(i, j - m.solved_from) += scale * inside(k + ri, j % k) / volume;
    }
  }
  return out;
}

// Rows per group of the condensed elimination, or 0 for the whole band: where every element
// column has one length, the one whose operation count is the lower (kAuto), the condensed one
// (kCondensed, its best grouping) or never (kBand). A band of n unknowns and half-width w factors
// in n w^2 / 2 multiply-adds and solves a right-hand side in 2 n w (the whole band's forward pass
// skips about a third: its loads start at their rows).
int GroupRows(const ElementMesh& m, AxialCoupling::Elimination elimination) {
  using Elimination = AxialCoupling::Elimination;
  if (elimination == Elimination::kBand) return 0;
  const double le = m.z[1] - m.z[0];
  for (int iz = 0; iz + 1 < m.nz; ++iz) {
    if (std::abs(m.z[static_cast<std::size_t>(iz) + 1] - m.z[static_cast<std::size_t>(iz)] - le) >
        1e-12 * le) {
      if (elimination == Elimination::kCondensed) {
        throw UserError(
            "axial coupling: the condensed elimination needs element columns of one "
            "length (rows of one length)");
      }
      return 0;
    }
  }
  const double w = m.Bandwidth(1, 2, [&m](int entry) { return m.unknown(entry); });
  const double line = static_cast<double>(m.free) / m.nz;  // unknowns per station
  const double loads = m.solved + (m.order == 1 ? 2 : 0);
  const double band = m.free * w * w / 2 + loads * 1.3 * m.free * w;
  int best = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= m.rows; ++k) {
    if (m.rows % k != 0) continue;
    const double inside = (m.per_row * k - 1) * line;
    const double patterns = m.order == 1 ? 2 * k + 1 : k;
    const double lines = (m.rows / k + 1) * line, width = 2 * line;
    // The inside's factor, its forward passes (the left line's coupling and the patterns; the
    // right line's covers one station) and their products, then the lines' band (counted whole:
    // its skipped zeros, BandCholesky's `block`, measured no better choice of k when counted).
    const double cost = inside * w * w / 2 + (line + patterns) * inside * w +
                        inside * (line + patterns) * (line + patterns) / 2 +
                        lines * width * width / 2 + loads * 2 * lines * width;
    if (cost < best_cost) {
      best_cost = cost;
      best = k;
    }
  }
  return elimination == Elimination::kCondensed || best_cost < band ? best : 0;
}

}  // namespace

AxialCoupling::AxialCoupling(const AxialBody& body, std::span<const double> row_edges, int order,
                             Elimination elimination)
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

  // Degrees of freedom, -1 where held: (U, W) per node for order 0, (U, V, W) for the others;
  // kTied: order 1's V on the axis.
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
  // Isotropic elasticity on (e_r, e_z, e_theta, g_rz, g_rtheta, g_thetaz).
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(nu);
  d.diagonal().head<3>().setConstant(1.0 - nu);
  d.diagonal().tail<3>().setConstant(0.5 - nu);
  d *= e / ((1.0 + nu) * (1.0 - 2.0 * nu));
  // Row j's unit pressure (per radian for order 0, per pi for the others, as the stiffness) is
  // p cos(n theta), R le / 2 on each end of each element of the loaded face, pushing the face away
  // from the other part; the same weights over the row's length average the face's radial
  // displacement: load_j = R length_j mean_j. So F = mean' K^-1 load, and mean' reads a row's few
  // face nodes. (Over the whole band, the Gram form R (L^-1 mean)' (L^-1 mean) diag(length) saves
  // the back substitution but costs rows^2 per unknown where the band costs twice its width: more
  // here; the condensed groups take it, their insides a few rows long.)
  const double face = r[loaded];
  const double open = body.loaded_inside ? 1.0 : -1.0;  // outwards opens a bore, inwards a shaft
  Eigen::VectorXd length(rows);
  for (int i = 0; i < rows; ++i) length[i] = row_edges[i + 1] - row_edges[i];
  // A part whose rows mirror about its middle is the same body loaded from either end (the
  // elements, the supports' effect and the body loads all mirror): F(i, j) = F(R-1-i, R-1-j), so
  // only the loads of the far half are solved. Their right-hand sides are zero until that half,
  // which the band's forward pass skips: 2.4 times fewer operations than every row's.
  bool mirrored = rows > 1;
  for (int i = 0; i < rows && mirrored; ++i) {
    mirrored = std::abs(length[i] - length[rows - 1 - i]) <= 1e-12 * length[i];
  }
  const int solved_from = mirrored ? rows / 2 : 0;  // the first row whose load is solved
  const int solved = rows - solved_from;
  const ElementMesh mesh{.body = &body,
                         .order = order,
                         .per_node = per_node,
                         .nr = nr,
                         .nz = nz,
                         .rows = rows,
                         .per_row = per_row,
                         .loaded = loaded,
                         .free = free,
                         .r = r,
                         .z = std::move(z),
                         .dof = std::move(dof),
                         .d = d,
                         .length = length,
                         .face = face,
                         .open = open,
                         .solved_from = solved_from,
                         .solved = solved};
  const int group_rows = GroupRows(mesh, elimination);
  Responses responses = group_rows > 0 ? CondensedResponses(mesh, group_rows) : BandResponses(mesh);
  Eigen::MatrixXd& half = responses.half;
  if (order == 1) {
    // A load cos(theta) has a net force and moment, which the rest of the model carries by the
    // part's rigid offset and tilt: here body forces b(z) = alpha + beta z (per unit volume,
    // along x: U-load b, V-load -b) balance each row's (inertia relief), so the supports carry
    // nothing. The two unit body loads once (Responses), each row's share by superposition. With
    // them each row's centroid displacement along x, the mean of u_x = U cos^2 - V sin^2 over its
    // volume (integral of (U - V) r dr dz / ((b^2 - a^2) L)): its line is the part's rigid motion.
    const Eigen::MatrixX2d& body_mean = responses.body_mean;
    const Eigen::MatrixX2d& body_centroid = responses.body_centroid;
    Eigen::MatrixXd& centroid = responses.centroid;
    const double a2 = mesh.RadiiSquared();
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

void AxialCoupling::ExtraDisplacement(const double* mean_pressure, double* out, Eigen::Index first,
                                      Eigen::Index count) const {
  // Most of a part's rows carry no pressure at a depth step (those out of the other part): their
  // columns are skipped, which changes no sum (TimesInOrder; the elements are finite).
  TimesInOrder(extra_, mean_pressure, out, first, count < 0 ? extra_.rows() - first : count,
               /*skip_zero=*/true);
}

}  // namespace fitfeel::cylindrical
