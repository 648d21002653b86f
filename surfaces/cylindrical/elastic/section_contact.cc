#include "surfaces/cylindrical/elastic/section_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

#include "framework/core/error.h"
#include "framework/core/least_norm.h"
#include "framework/core/simd_clones.h"

namespace fitfeel::cylindrical {
namespace {

// Rows j .. j + B of AddScaledColumns, their B sums held in registers over every column.
template <int B>
inline void AddScaledColumnRows(double* __restrict sum, const double* __restrict matrix,
                                const int* cols, const double* __restrict coeff, int count, int n,
                                int j) {
  FITFEEL_NO_FP_CONTRACT
  double acc[B];
  for (int r = 0; r < B; ++r) acc[r] = 0.0;
  for (int a = 0; a < count; ++a) {
    const double* __restrict column =
        matrix + static_cast<std::ptrdiff_t>(cols != nullptr ? cols[a] : a) * n + j;
    const double c = coeff[a];
    for (int r = 0; r < B; ++r) acc[r] += c * column[r];
  }
  for (int r = 0; r < B; ++r) sum[j + r] = acc[r];
}

// sum = sum over a < count of coeff[a] * column cols[a] (or column a without cols) of the
// column-major n x n `matrix`: the solver's products with whole contiguous columns, compiled
// also for AVX2 and AVX-512 (framework/core/simd_clones.h; each sum[j] adds in the order of a).
FITFEEL_SIMD_CLONES void AddScaledColumns(double* __restrict sum, const double* __restrict matrix,
                                          const int* cols, const double* __restrict coeff,
                                          int count, int n) {
  FITFEEL_NO_FP_CONTRACT
  int j = 0;
  for (; j + 16 <= n; j += 16) AddScaledColumnRows<16>(sum, matrix, cols, coeff, count, n, j);
  for (; j + 4 <= n; j += 4) AddScaledColumnRows<4>(sum, matrix, cols, coeff, count, n, j);
  for (; j < n; ++j) AddScaledColumnRows<1>(sum, matrix, cols, coeff, count, n, j);
}

}  // namespace

CirculantContact::CirculantContact(const std::vector<double>& compliance, int n) : n_(n) {
  if (n < 4 || n % 2 != 0 || compliance.size() != static_cast<std::size_t>(n / 2 + 1)) {
    throw UserError("circulant contact needs an even column count >= 4 and n/2 + 1 compliances");
  }
  for (double c : compliance) {
    if (!(c > 0.0) || !std::isfinite(c)) throw UserError("compliances must be positive");
  }
  // First column of the circulant: the inverse real DFT of the compliance spectrum.
  std::vector<double> col(static_cast<std::size_t>(n), 0.0);
  for (int m = 0; m < n; ++m) {
    double s = compliance[0] + compliance[static_cast<std::size_t>(n / 2)] * ((m % 2) ? -1.0 : 1.0);
    for (int k = 1; k < n / 2; ++k) {
      s += 2.0 * compliance[static_cast<std::size_t>(k)] *
           std::cos(2.0 * std::numbers::pi * k * m / n);
    }
    col[static_cast<std::size_t>(m)] = s / n;
  }
  g_.resize(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) g_(i, j) = col[static_cast<std::size_t>((i - j + n) % n)];
  }
  cos_.resize(static_cast<std::size_t>(n));
  sin_.resize(static_cast<std::size_t>(n));
  Eigen::MatrixXd u(n, 2);
  for (int j = 0; j < n; ++j) {
    cos_[static_cast<std::size_t>(j)] = std::cos(2.0 * std::numbers::pi * j / n);
    sin_[static_cast<std::size_t>(j)] = std::sin(2.0 * std::numbers::pi * j / n);
    u(j, 0) = cos_[static_cast<std::size_t>(j)];
    u(j, 1) = sin_[static_cast<std::size_t>(j)];
  }
  g_inv_ = g_.llt().solve(Eigen::MatrixXd::Identity(n, n));
  inverse_ones_ = g_inv_.rowwise().sum();
  g_inv_u_ = g_inv_ * u;
  full_stiffness_ = u.transpose() * g_inv_u_;
}

void CirculantContact::InverseTimes(const double* x, double* out) const {
  AddScaledColumns(out, g_inv_.data(), nullptr, x, n_, n_);
}

bool CirculantContact::SolveFull(const Eigen::Vector2d& e, const double* inverse_gap, double* p,
                                 std::vector<char>* active, Factorization* workspace) {
  // The pressures, then whether any is negative (or NaN): two loops that vectorise.
  const double* u0 = g_inv_u_.col(0).data();
  const double* u1 = g_inv_u_.col(1).data();
  for (int j = 0; j < n_; ++j) p[j] = u0[j] * e.x() + u1[j] * e.y() - inverse_gap[j];
  int infeasible = 0;
  for (int j = 0; j < n_; ++j) infeasible |= p[j] >= 0.0 ? 0 : 1;
  if (infeasible != 0) return false;
  active->assign(static_cast<std::size_t>(n_), 1);
  last_ = workspace;
  (workspace != nullptr ? *workspace : own_).last_full = true;
  return true;
}

namespace {
constexpr const char* kNotDefinite =
    "section contact: a principal submatrix of the compliance is not positive definite (to "
    "rounding); the compliance spectrum must be positive";
}  // namespace

void CirculantContact::Refactor(const Eigen::MatrixXd& a, std::vector<int>* target,
                                Factorization::Factor* factor, std::vector<char>* mark) const {
  std::vector<int>& held = factor->columns;
  DenseCholesky& chol = factor->cholesky;
  if (factor->valid) {
    // What leaves and what joins, by membership flags over the n columns.
    mark->assign(static_cast<std::size_t>(n_), 0);
    for (int c : *target) (*mark)[static_cast<std::size_t>(c)] = 1;
    int leaving = 0;
    for (int c : held) leaving += (*mark)[static_cast<std::size_t>(c)] ? 0 : 1;
    const int joining =
        static_cast<int>(target->size()) - (static_cast<int>(held.size()) - leaving);
    // Row updates cost about 2 m^2 each against m^3 / 3 for a new factor.
    if (6 * (leaving + joining) <= static_cast<int>(target->size())) {
      bool ok = true;
      for (int pos = static_cast<int>(held.size()) - 1; pos >= 0 && leaving > 0; --pos) {
        if (!(*mark)[static_cast<std::size_t>(held[static_cast<std::size_t>(pos)])]) {
          chol.Remove(pos);
          held.erase(held.begin() + pos);
          --leaving;
        }
      }
      for (int c : held) (*mark)[static_cast<std::size_t>(c)] = 2;  // held and wanted
      Eigen::VectorXd column;
      for (int c : *target) {
        if ((*mark)[static_cast<std::size_t>(c)] == 2) continue;
        column.resize(static_cast<Eigen::Index>(held.size()));
        for (std::size_t r = 0; r < held.size(); ++r)
          column[static_cast<Eigen::Index>(r)] = a(held[r], c);
        if (!chol.Append(column, a(c, c))) {
          ok = false;
          break;
        }
        held.push_back(c);
      }
      if (ok) {
        *target = held;
        return;
      }
    }
  }
  held = *target;
  factor->valid = chol.Compute(a, held);
  if (!factor->valid) throw UserError(kNotDefinite);
}

int CirculantContact::Solve(const double* delta, double* p, std::vector<char>* active,
                            const double* full, Factorization* workspace) {
  Factorization& ws = workspace != nullptr ? *workspace : own_;
  last_ = workspace;
  const int n = n_;
  std::vector<char>& f = *active;
  if (static_cast<int>(f.size()) != n) f.assign(static_cast<std::size_t>(n), 0);
  // The largest |delta| over four lanes (a maximum is exact in any order).
  std::array<double, 4> lane{0.0, 0.0, 0.0, 0.0};
  int at = 0;
  for (; at + 4 <= n; at += 4) {
    for (int l = 0; l < 4; ++l) lane[l] = std::max(lane[l], std::abs(delta[at + l]));
  }
  for (; at < n; ++at) lane[0] = std::max(lane[0], std::abs(delta[at]));
  const double scale = std::max(std::max(lane[0], lane[1]), std::max(lane[2], lane[3]));
  // Tolerances relative to the data: a closure error of 1e-12 of the largest interference (and the
  // pressure that would cause it) is rounding, not contact.
  const double tol_w = 1e-12 * scale + 1e-300;
  const double tol_p = tol_w / g_(0, 0);
  int best = n + 1, chances = 3, steps = 0;
  w_.setZero(n);
  ws.last_full = false;
  // y = G^-1 delta: the pressures of full contact, and the right-hand side of the dual step.
  if (full == nullptr) {
    full_.resize(n);
    InverseTimes(delta, full_.data());
    if (full_.minCoeff() >= 0.0) {
      for (int j = 0; j < n; ++j) p[j] = full_[j];
      f.assign(static_cast<std::size_t>(n), 1);
      ws.last_full = true;
      return 1;
    }
  } else {
    full_ = Eigen::Map<const Eigen::VectorXd>(full, n);
  }
  while (true) {
    ++steps;
    if (steps > 20 * n + 50) {
      throw UserError("section contact: pivoting did not terminate (" + std::to_string(steps) +
                      " steps); the compliance is not positive definite?");
    }
    // The contact set and the gaps, ascending: written through raw pointers into vectors sized
    // for every column (a push_back per column kept the vectors' ends in memory between columns,
    // and the flags' unpredictable branch on top of it).
    ws.index.resize(static_cast<std::size_t>(n));
    ws.gaps.resize(static_cast<std::size_t>(n));
    int m = 0, k = 0;
    {
      int* const in = ws.index.data();
      int* const out = ws.gaps.data();
      for (int j = 0; j < n; ++j) {
        const bool touching = f[static_cast<std::size_t>(j)] != 0;
        in[m] = j;
        out[k] = j;
        m += touching ? 1 : 0;
        k += touching ? 0 : 1;
      }
    }
    ws.index.resize(static_cast<std::size_t>(m));
    ws.gaps.resize(static_cast<std::size_t>(k));
    std::fill(p, p + n, 0.0);
    // Pressures on the contact set F and closures on the gaps N = the rest, by whichever system is
    // smaller: G_FF p_F = delta_F (m^3) or, with H = G^-1 and y = H delta, the dual
    // H_NN z = y_N, p_F = y_F - H_FN z, closure minus interference w_N = -z (k^3): the
    // same solution (block inverse of G), found at a cost set by the fewer of contacts and gaps.
    ws.dual = k < m;
    if (ws.dual) {
      Refactor(g_inv_, &ws.gaps, &ws.dual_factor, &ws.mark);
      z_ = full_(ws.gaps);
      ws.dual_factor.cholesky.SolveInPlace(z_);
      // H_FN z as whole columns of H (contiguous, vectorised) over all n rows, read on F.
      sum_.resize(n);
      AddScaledColumns(sum_.data(), g_inv_.data(), ws.gaps.data(), z_.data(), k, n);
      for (int c : ws.index) p[c] = full_[c] - sum_[c];
      for (int a = 0; a < k; ++a) w_[ws.gaps[static_cast<std::size_t>(a)]] = -z_[a];
    } else {
      // p_F in the factor's order (Refactor's) in coeff_, then in place.
      coeff_.resize(m);
      if (m > 0) {
        Refactor(g_, &ws.index, &ws.primal, &ws.mark);
        for (int a = 0; a < m; ++a) coeff_[a] = delta[ws.index[static_cast<std::size_t>(a)]];
        ws.primal.cholesky.SolveInPlace(coeff_);
        for (int a = 0; a < m; ++a) p[ws.index[static_cast<std::size_t>(a)]] = coeff_[a];
      }
      // G_NF p_F as whole columns of G over all n rows, read on N.
      sum_.resize(n);
      AddScaledColumns(sum_.data(), g_.data(), ws.index.data(), coeff_.data(), m, n);
      for (int j : ws.gaps) w_[j] = sum_[j] - delta[j];
    }
    // Both tests on every column, the flag choosing (w_ holds a defined value everywhere): no
    // branch on the flags, which the pivoting leaves in no predictable pattern.
    int infeasible = 0, last = -1;
    for (int j = 0; j < n; ++j) {
      const int touching = f[static_cast<std::size_t>(j)] != 0 ? 1 : 0;
      const int bad =
          (touching & (p[j] < -tol_p ? 1 : 0)) | ((touching ^ 1) & (w_[j] < -tol_w ? 1 : 0));
      infeasible += bad;
      last = bad != 0 ? j : last;
    }
    if (infeasible == 0) break;
    if (infeasible < best) {
      best = infeasible;
      chances = 3;
    } else if (chances > 0) {
      --chances;
    } else {
      // Murty: flip only the largest infeasible index; finite by a lexicographic argument.
      f[static_cast<std::size_t>(last)] = !f[static_cast<std::size_t>(last)];
      continue;
    }
    for (int j = 0; j < n; ++j) {
      const bool bad = f[static_cast<std::size_t>(j)] ? p[j] < -tol_p : w_[j] < -tol_w;
      if (bad) f[static_cast<std::size_t>(j)] = !f[static_cast<std::size_t>(j)];
    }
  }
  for (int j = 0; j < n; ++j) p[j] = std::max(p[j], 0.0);
  return steps;
}

Eigen::Matrix2d CirculantContact::OffsetStiffness() const {
  const Factorization& ws = last_ != nullptr ? *last_ : own_;
  if (ws.last_full) return full_stiffness_;
  if (ws.dual) {
    // U_F^T G_FF^-1 U_F = U^T H U - A_N^T H_NN^-1 A_N with A = H U (the block inverse again).
    const int k = static_cast<int>(ws.gaps.size());
    Eigen::MatrixX2d a(k, 2);
    for (int r = 0; r < k; ++r) a.row(r) = g_inv_u_.row(ws.gaps[static_cast<std::size_t>(r)]);
    return full_stiffness_ - ws.dual_factor.cholesky.InverseForm(std::move(a));
  }
  const int m = static_cast<int>(ws.index.size());
  if (m == 0) return Eigen::Matrix2d::Zero();
  Eigen::MatrixX2d u(m, 2);
  for (int a = 0; a < m; ++a) {
    u(a, 0) = cos_[static_cast<std::size_t>(ws.index[static_cast<std::size_t>(a)])];
    u(a, 1) = sin_[static_cast<std::size_t>(ws.index[static_cast<std::size_t>(a)])];
  }
  return ws.primal.cholesky.InverseForm(std::move(u));
}

Eigen::MatrixXd CirculantContact::ShiftStiffness(const Factorization& ws,
                                                 const Eigen::MatrixXd& basis,
                                                 const Eigen::MatrixXd& inverse_basis,
                                                 const Eigen::MatrixXd& full) const {
  if (ws.last_full) return full;
  if (ws.dual) {
    // As OffsetStiffness: B_F^T G_FF^-1 B_F = B^T H B - A_N^T H_NN^-1 A_N with A = H B.
    const auto k = static_cast<Eigen::Index>(ws.gaps.size());
    Eigen::MatrixXd a(k, basis.cols());
    for (Eigen::Index r = 0; r < k; ++r) {
      a.row(r) = inverse_basis.row(ws.gaps[static_cast<std::size_t>(r)]);
    }
    return full - ws.dual_factor.cholesky.InverseFormOf(std::move(a));
  }
  const auto m = static_cast<Eigen::Index>(ws.index.size());
  if (m == 0) return Eigen::MatrixXd::Zero(basis.cols(), basis.cols());
  Eigen::MatrixXd u(m, basis.cols());
  for (Eigen::Index r = 0; r < m; ++r) u.row(r) = basis.row(ws.index[static_cast<std::size_t>(r)]);
  return ws.primal.cholesky.InverseFormOf(std::move(u));
}

RigidSectionContact::RigidSectionContact(const PressFitSection& section, int n_columns,
                                         const std::vector<int>& shift_orders)
    : contact_(CirculantCompliance(section, n_columns), n_columns) {
  cos_.resize(static_cast<std::size_t>(n_columns));
  sin_.resize(static_cast<std::size_t>(n_columns));
  for (int j = 0; j < n_columns; ++j) {
    cos_[static_cast<std::size_t>(j)] = std::cos(2.0 * std::numbers::pi * j / n_columns);
    sin_[static_cast<std::size_t>(j)] = std::sin(2.0 * std::numbers::pi * j / n_columns);
  }
  const auto components = static_cast<Eigen::Index>(1 + 2 * shift_orders.size());
  shift_basis_.resize(n_columns, components);
  shift_basis_.col(0).setOnes();
  for (std::size_t o = 0; o < shift_orders.size(); ++o) {
    const int order = shift_orders[o];
    if (order < 1 || 2 * order > n_columns) {
      throw UserError("a section's gap shift takes orders 1 to columns / 2, not " +
                      std::to_string(order));
    }
    for (int j = 0; j < n_columns; ++j) {
      // The integer product modulo n keeps the angle exact for every order.
      const double angle = 2.0 * std::numbers::pi * ((order * j) % n_columns) / n_columns;
      shift_basis_(j, static_cast<Eigen::Index>(1 + 2 * o)) = std::cos(angle);
      shift_basis_(j, static_cast<Eigen::Index>(2 + 2 * o)) = std::sin(angle);
    }
  }
  // The basis with the offset's directions (cos, sin) appended, for ShiftStiffness.
  response_basis_.resize(n_columns, components + 2);
  response_basis_.leftCols(components) = shift_basis_;
  for (int j = 0; j < n_columns; ++j) {
    response_basis_(j, components) = cos_[static_cast<std::size_t>(j)];
    response_basis_(j, components + 1) = sin_[static_cast<std::size_t>(j)];
  }
  inverse_response_basis_.resize(n_columns, components + 2);
  inverse_response_basis_.col(0) = contact_.inverse_ones();
  for (Eigen::Index c = 1; c < components + 2; ++c) {
    contact_.InverseTimes(response_basis_.col(c).data(), inverse_response_basis_.col(c).data());
  }
  full_response_ = response_basis_.transpose() * inverse_response_basis_;
}

double RigidSectionContact::Evaluate(std::span<const ContactSection> sections,
                                     const RigidFreedom& freedom, const Eigen::Vector4d& q,
                                     Eigen::Vector4d* grad, Eigen::Matrix4d* hess) {
  const int n = contact_.columns();
  const auto nn = static_cast<std::size_t>(n);
  delta_.resize(nn);
  pressure_.resize(sections.size() * nn);
  if (active_.size() != sections.size()) active_.assign(sections.size(), std::vector<char>(nn, 0));
  workspace_.assign(sections.size(), nullptr);
  const Eigen::Vector2d e0 = q.head<2>(), t = q.tail<2>();
  double phi = 0.0;
  grad->setZero();
  hess->setZero();
  for (std::size_t s = 0; s < sections.size(); ++s) {
    const ContactSection& sec = sections[s];
    const Eigen::Vector2d e = freedom.tilt ? Eigen::Vector2d(e0 + sec.y * t) : e0;
    double* p = pressure_.data() + s * nn;
    // The interference and whether any column has one, as two loops that vectorise.
    for (std::size_t j = 0; j < nn; ++j) {
      delta_[j] = e.x() * cos_[j] + e.y() * sin_[j] - sec.gap[j];
    }
    int any = 0;
    for (std::size_t j = 0; j < nn; ++j) any |= delta_[j] > 0.0 ? 1 : 0;
    if (any == 0 &&
        std::none_of(active_[s].begin(), active_[s].end(), [](char a) { return a != 0; })) {
      std::fill(p, p + n, 0.0);
      workspace_[s] = nullptr;
      continue;
    }
    CirculantContact::Factorization* factors =
        sec.factorization != nullptr ? sec.factorization : &factors_[s];
    workspace_[s] = factors;
    // Full contact's pressures straight into p; where one is negative they are Solve's `full`
    // (which it reads before it writes p).
    if (!contact_.SolveFull(e, InverseGap(sec, s), p, &active_[s], factors)) {
      contact_.Solve(delta_.data(), p, &active_[s], p, factors);
    }
    double energy = 0.0;
    Eigen::Vector2d f(0.0, 0.0);
    for (std::size_t j = 0; j < nn; ++j) {
      energy += delta_[j] * p[j];
      f += p[j] * Eigen::Vector2d(cos_[j], sin_[j]);
    }
    phi += 0.5 * sec.cell_area * energy;
    f *= sec.cell_area;
    const Eigen::Matrix2d k = sec.cell_area * contact_.OffsetStiffness();
    grad->head<2>() += f;
    hess->topLeftCorner<2, 2>() += k;
    if (freedom.tilt) {
      grad->tail<2>() += sec.y * f;
      hess->topRightCorner<2, 2>() += sec.y * k;
      hess->bottomLeftCorner<2, 2>() += sec.y * k;
      hess->bottomRightCorner<2, 2>() += sec.y * sec.y * k;
    }
  }
  phi -= freedom.force.dot(e0);
  if (freedom.tilt) phi += 0.5 * freedom.tilt_stiffness * t.squaredNorm() - freedom.moment.dot(t);
  grad->head<2>() -= freedom.force;
  if (freedom.tilt) {
    grad->tail<2>() += freedom.tilt_stiffness * t - freedom.moment;
    hess->bottomRightCorner<2, 2>() += freedom.tilt_stiffness * Eigen::Matrix2d::Identity();
  }
  return phi;
}

const double* RigidSectionContact::InverseGap(const ContactSection& section, std::size_t index) {
  const auto n = static_cast<std::size_t>(columns());
  double* out = inverse_gap_.data() + index * n;
  if (!inverse_gap_ready_[index]) {
    contact_.InverseTimes(section.gap, out);
    inverse_gap_ready_[index] = 1;
  }
  return out;
}

double RigidSectionContact::DistanceToContact(std::span<const ContactSection> sections,
                                              const RigidFreedom& freedom, const Eigen::Vector4d& q,
                                              const Eigen::Vector4d& dir) const {
  double reach = std::numeric_limits<double>::infinity();
  for (const ContactSection& sec : sections) {
    const double y = freedom.tilt ? sec.y : 0.0;
    const Eigen::Vector2d e = q.head<2>() + y * q.tail<2>();
    const Eigen::Vector2d de = dir.head<2>() + y * dir.tail<2>();
    for (std::size_t j = 0; j < cos_.size(); ++j) {
      const double rate = de.x() * cos_[j] + de.y() * sin_[j];
      if (!(rate > 0.0)) continue;
      const double gap = sec.gap[j] - (e.x() * cos_[j] + e.y() * sin_[j]);
      reach = std::min(reach, std::max(gap, 0.0) / rate);
    }
  }
  return reach;
}

RigidContactResult RigidSectionContact::Solve(std::span<const ContactSection> sections,
                                              const RigidFreedom& freedom,
                                              const Eigen::Vector4d& warm,
                                              std::span<const double> gap_shift, double handoff) {
  const auto nn = static_cast<std::size_t>(columns());
  Eigen::Vector4d q = warm;
  if (!freedom.tilt) q.tail<2>().setZero();
  active_.resize(sections.size());
  // Each section's pivoting starts from its warm set, less the columns whose gap at the starting
  // pose is open by more than the section's largest interference. Columns open by less stay: the
  // compliance is negative a quarter turn from a load (the parts ovalise), so the pressure on the
  // interfering columns closes gaps elsewhere, and such columns are often in the answer's set
  // (an H7/n6: 14 % of its contact columns). Dropping every open column would make the pivoting
  // add them back: that H7/n6's LCPs would join 168 k columns and leave 25 k over the prepare,
  // 41 % of them in 4 to 6 pivoting steps, where the margin gives 46 k and 38 k, 4 %. Keeping
  // every warm column would also keep those a light fit's sections have left for good (H7/js6's
  // prepare 10 % slower than with the margin).
  for (std::size_t s = 0; s < sections.size(); ++s) {
    const char* w = sections[s].warm_contact;
    active_[s].assign(nn, 0);
    if (w == nullptr) continue;
    const double y = freedom.tilt ? sections[s].y : 0.0;
    const Eigen::Vector2d e = q.head<2>() + y * q.tail<2>();
    delta_.resize(nn);
    for (std::size_t j = 0; j < nn; ++j) {
      delta_[j] = e.x() * cos_[j] + e.y() * sin_[j] - sections[s].gap[j];
    }
    // The largest of 0 and the interferences, over four lanes (a maximum is exact in any order).
    std::array<double, 4> lane{0.0, 0.0, 0.0, 0.0};
    std::size_t j = 0;
    for (; j + 4 <= nn; j += 4) {
      for (std::size_t l = 0; l < 4; ++l) lane[l] = std::max(lane[l], delta_[j + l]);
    }
    for (; j < nn; ++j) lane[0] = std::max(lane[0], delta_[j]);
    const double largest = std::max(std::max(lane[0], lane[1]), std::max(lane[2], lane[3]));
    char* flags = active_[s].data();
    for (j = 0; j < nn; ++j) flags[j] = (w[j] != 0) & (delta_[j] > -largest);
  }
  const auto components = static_cast<std::size_t>(shift_basis_.cols());
  if (!gap_shift.empty() && gap_shift.size() == sections.size() * components &&
      inverse_gap_ready_.size() == sections.size()) {
    ShiftInverseGaps(gap_shift);
  } else {
    inverse_gap_.resize(sections.size() * nn);
    inverse_gap_ready_.assign(sections.size(), 0);
  }
  factors_.resize(sections.size());
  for (CirculantContact::Factorization& f : factors_) f.Invalidate();
  double length = 0.0;
  for (const ContactSection& s : sections) length = std::max(length, std::abs(s.y));
  length = std::max(length, 1e-6);
  RigidContactResult r;
  // Every evaluation computes the derivatives too, so that a line search's accepted point is the
  // next Newton iterate without a second evaluation there (the LCPs are most of the cost).
  Eigen::Vector4d grad, trial_grad;
  Eigen::Matrix4d hess, trial_hess;
  double phi = Evaluate(sections, freedom, q, &grad, &hess);
  bool evaluated_at_q = true;  // pressure_ and active_ belong to q
  r.converged = false;
  r.next = q;
  for (int it = 0; it < 60; ++it) {
    ++r.newton_iterations;
    // Force scale of the problem: what the sections carry and what is applied.
    double load = freedom.force.norm() + freedom.moment.norm() / length;
    for (std::size_t s = 0; s < sections.size(); ++s) {
      double sum = 0.0;
      for (std::size_t j = 0; j < nn; ++j) sum += pressure_[s * nn + j];
      load += sum * sections[s].cell_area;
    }
    Eigen::Vector4d scaled = grad;
    scaled.tail<2>() /= length;
    if (scaled.norm() <= 1e-10 * load + 1e-12) {
      r.converged = true;
      break;
    }
    const bool hand_off = scaled.norm() <= handoff * load;
    const int dofs = freedom.tilt ? 4 : 2;
    Eigen::MatrixXd h = hess.topLeftCorner(dofs, dofs);
    const double tr = h.trace();
    if (!(tr > 0.0)) {
      // Nothing touches yet, but a load pushes: move along it to the first touching column.
      Eigen::Vector4d dir = Eigen::Vector4d::Zero();
      dir.head(dofs) = -grad.head(dofs);
      dir.tail<2>() /= length * length;
      const double reach = DistanceToContact(sections, freedom, q, dir);
      if (!std::isfinite(reach)) {
        throw UserError("rigid contact: the load pushes the part where nothing holds it");
      }
      // A picometre past touching, so that the contact has a stiffness for the Newton step.
      Eigen::Vector4d unit = dir;
      unit.tail<2>() *= length;
      q += (reach + 1e-12 / unit.norm()) * dir;
      phi = Evaluate(sections, freedom, q, &grad, &hess);
      continue;
    }
    const Eigen::VectorXd step = -LeastNormSolve(h, grad.head(dofs));
    Eigen::Vector4d dir = Eigen::Vector4d::Zero();
    dir.head(dofs) = step;
    const double slope = grad.dot(dir);
    if (!(slope < 0.0)) break;
    if (hand_off) {
      r.next = q + dir;  // the caller evaluates it (with its gaps moved)
      break;
    }
    double alpha = 1.0;
    bool accepted = false;
    while (alpha > 1e-12) {
      const double trial = Evaluate(sections, freedom, q + alpha * dir, &trial_grad, &trial_hess);
      if (trial <= phi + 1e-4 * alpha * slope) {
        phi = trial;
        accepted = true;
        break;
      }
      alpha *= 0.5;
    }
    if (!accepted) {
      evaluated_at_q = false;  // the last evaluation was a rejected trial
      break;
    }
    grad = trial_grad;
    hess = trial_hess;
    q += alpha * dir;
    Eigen::Vector4d moved = alpha * dir;
    moved.tail<2>() *= length;
    if (moved.norm() < 1e-15) break;  // a femtometre: converged to rounding
  }
  if (!evaluated_at_q) Evaluate(sections, freedom, q, &grad, &hess);
  if (r.converged || r.next == q) {
    r.converged = true;  // at rounding or out of steps without a better point: where it is
    r.next = q;
  }
  r.offset = q.head<2>();
  r.tilt = freedom.tilt ? Eigen::Vector2d(q.tail<2>()) : Eigen::Vector2d::Zero();
  for (std::size_t s = 0; s < sections.size(); ++s) {
    for (std::size_t j = 0; j < nn; ++j) {
      const double p = pressure_[s * nn + j];
      r.normal_force += p * sections[s].cell_area;
      r.resultant += p * sections[s].cell_area * Eigen::Vector2d(cos_[j], sin_[j]);
      r.max_pressure = std::max(r.max_pressure, p);
    }
  }
  return r;
}

Eigen::MatrixXd RigidSectionContact::ShiftStiffness(std::size_t section) const {
  const auto size = response_basis_.cols();
  if (section >= workspace_.size() || workspace_[section] == nullptr) {
    return Eigen::MatrixXd::Zero(size, size);
  }
  return contact_.ShiftStiffness(*workspace_[section], response_basis_, inverse_response_basis_,
                                 full_response_);
}

Eigen::MatrixXd SectionPlacement(const ContactSection& section, const RigidFreedom& freedom) {
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(2, freedom.tilt ? 4 : 2);
  p.leftCols<2>().setIdentity();
  if (freedom.tilt) p.rightCols<2>() = section.y * Eigen::Matrix2d::Identity();
  return p;
}

void RigidSectionContact::ShiftInverseGaps(std::span<const double> shift) {
  // The same sections with every gap of section s grown by its shift's components: G^-1 is
  // linear, so the products known from the last Solve move by the components' G^-1 b_c (O(n)
  // each, not O(n^2)).
  const auto nn = static_cast<std::size_t>(columns());
  const auto components = static_cast<std::size_t>(shift_basis_.cols());
  for (std::size_t s = 0; s < inverse_gap_ready_.size(); ++s) {
    if (!inverse_gap_ready_[s]) continue;
    Eigen::Map<Eigen::VectorXd> out(inverse_gap_.data() + s * nn, static_cast<Eigen::Index>(nn));
    for (std::size_t c = 0; c < components; ++c) {
      if (const double a = shift[s * components + c]; a != 0.0) {
        out += a * inverse_response_basis_.col(static_cast<Eigen::Index>(c));
      }
    }
  }
}

bool RigidSectionContact::ShiftFullContact(std::span<const ContactSection> sections,
                                           const RigidFreedom& freedom,
                                           std::span<const double> shift,
                                           RigidContactResult* result) {
  const auto nn = static_cast<std::size_t>(columns());
  const auto nc = shift_basis_.cols();
  const auto components = static_cast<std::size_t>(nc);
  if (sections.size() != active_.size() || shift.size() != sections.size() * components ||
      pressure_.size() != sections.size() * nn) {
    return false;
  }
  for (const std::vector<char>& set : active_) {
    for (char a : set) {
      if (!a) return false;
    }
  }
  // In contact all round everything is linear: the pressures move by -G^-1 B x_s, and by
  // G^-1 U P_s dq where the part's offset and tilt answer the net forces the shifts make
  // (order 1's; the others have none), H dq = sum_s A_s P_s^T U^T G^-1 B x_s.
  const int dofs = freedom.tilt ? 4 : 2;
  const auto inverse_b = inverse_response_basis_.leftCols(nc);
  const auto inverse_u = inverse_response_basis_.rightCols(2);
  // U^T G^-1 B and U^T G^-1 U: E^T G^-1 E's last two rows.
  const auto ub = full_response_.bottomLeftCorner(2, nc);
  const Eigen::Matrix2d uu = full_response_.bottomRightCorner<2, 2>();
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(dofs);
  auto place = [&](const ContactSection& section) { return SectionPlacement(section, freedom); };
  for (std::size_t s = 0; s < sections.size(); ++s) {
    const Eigen::MatrixXd p = place(sections[s]);
    const Eigen::Map<const Eigen::VectorXd> x(shift.data() + s * components, nc);
    h += sections[s].cell_area * p.transpose() * uu * p;
    rhs += sections[s].cell_area * p.transpose() * (ub * x);
  }
  if (dofs == 4) h.bottomRightCorner<2, 2>().diagonal().array() += freedom.tilt_stiffness;
  const Eigen::VectorXd dq = LeastNormSolve(h, rhs);
  shifted_.resize(sections.size() * nn);
  for (std::size_t s = 0; s < sections.size(); ++s) {
    Eigen::Map<Eigen::VectorXd> change(shifted_.data() + s * nn, static_cast<Eigen::Index>(nn));
    const Eigen::Map<const Eigen::VectorXd> x(shift.data() + s * components, nc);
    change = inverse_u * (place(sections[s]) * dq) - inverse_b * x;
    for (std::size_t j = 0; j < nn; ++j) {
      if (!(pressure_[s * nn + j] + change[static_cast<Eigen::Index>(j)] >= 0.0)) return false;
    }
  }
  // The gaps the caller moved: what a later Solve with a shift from here starts from.
  if (inverse_gap_ready_.size() == sections.size()) ShiftInverseGaps(shift);
  result->offset += dq.head<2>();
  if (dofs == 4) result->tilt += dq.tail<2>();
  result->next << result->offset, result->tilt;
  result->normal_force = 0.0;
  result->max_pressure = 0.0;
  result->resultant.setZero();
  for (std::size_t s = 0; s < sections.size(); ++s) {
    for (std::size_t j = 0; j < nn; ++j) {
      double& p = pressure_[s * nn + j];
      p += shifted_[s * nn + j];
      result->normal_force += p * sections[s].cell_area;
      result->resultant += p * sections[s].cell_area * Eigen::Vector2d(cos_[j], sin_[j]);
      result->max_pressure = std::max(result->max_pressure, p);
    }
  }
  return true;
}

}  // namespace fitfeel::cylindrical
