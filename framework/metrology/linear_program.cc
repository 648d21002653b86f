#include "framework/metrology/linear_program.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/LU>

namespace fitfeel::metrology {
namespace {

// Revised simplex for min cost . y s.t. M y = r (r >= 0), y >= 0, over the columns of M plus d
// artificial identity columns (indices N .. N+d-1). The basis inverse is recomputed from scratch
// each pivot: with d <= ~8 that costs nothing next to pricing N columns. The pivots' matrices and
// vectors are members, sized once: a skin model's checks solve thousands of these programs.
class DualSimplex {
 public:
  DualSimplex(const Eigen::MatrixXd& M, const Eigen::VectorXd& r)
      : M_(M), r_(r), d_(static_cast<int>(M.rows())), n_(static_cast<int>(M.cols())) {
    basis_.resize(d_);
    for (int i = 0; i < d_; ++i) basis_[i] = n_ + i;
    B_.resize(d_, d_);
    cb_.resize(d_);
    xb_.resize(d_);
    w_.resize(d_);
    column_.resize(d_);
    in_basis_.assign(static_cast<std::size_t>(n_ + d_), 0);
  }

  // Column k of [M I] into column_.
  const Eigen::VectorXd& Column(int k) {
    if (k < n_) {
      column_ = M_.col(k);
    } else {
      column_.setZero();
      column_(k - n_) = 1.0;
    }
    return column_;
  }

  // Runs simplex with the given costs (size n_ + d_); artificial columns may enter only if
  // `allow_artificial`. Returns false if unbounded.
  bool Run(const Eigen::VectorXd& cost, bool allow_artificial, int* iterations) {
    const double tol = 1e-10;
    int degenerate_run = 0;
    const long max_iterations = 50L * (n_ + d_) + 1000;
    for (long it = 0; it < max_iterations; ++it) {
      for (int i = 0; i < d_; ++i) {
        B_.col(i) = Column(basis_[i]);
        cb_(i) = cost(basis_[i]);
      }
      lu_.compute(B_);
      xb_ = lu_.solve(r_);
      pi_ = lu_.transpose().solve(cb_);
      // Pricing: Dantzig (most negative reduced cost), or Bland (lowest index) to break cycles.
      const bool bland = degenerate_run > 20;
      int entering = -1;
      double best = -tol;
      const int limit = allow_artificial ? n_ + d_ : n_;
      std::fill(in_basis_.begin(), in_basis_.end(), 0);
      for (int i = 0; i < d_; ++i) in_basis_[basis_[i]] = 1;
      reduced_.noalias() = cost.head(n_) - M_.transpose() * pi_;
      for (int k = 0; k < limit; ++k) {
        if (in_basis_[k]) continue;
        const double reduced = k < n_ ? reduced_(k) : cost(k) - pi_(k - n_);
        if (reduced < best) {
          entering = k;
          best = reduced;
          if (bland) break;
        }
      }
      if (entering < 0) return true;
      w_ = lu_.solve(Column(entering));
      int leaving = -1;
      double ratio = std::numeric_limits<double>::infinity();
      for (int i = 0; i < d_; ++i) {
        if (w_(i) > tol) {
          const double q = std::max(0.0, xb_(i)) / w_(i);
          if (q < ratio - 1e-14 ||
              (q <= ratio + 1e-14 && leaving >= 0 && bland && basis_[i] < basis_[leaving])) {
            ratio = q;
            leaving = i;
          }
        }
      }
      if (leaving < 0) return false;
      degenerate_run = ratio < 1e-14 ? degenerate_run + 1 : 0;
      basis_[leaving] = entering;
      ++*iterations;
    }
    throw std::runtime_error("linear program: simplex did not converge");
  }

  // After phase 1, replaces artificial basics (at level zero) by real columns where possible.
  void DriveOutArtificials() {
    for (int i = 0; i < d_; ++i) {
      if (basis_[i] < n_) continue;
      for (int q = 0; q < d_; ++q) B_.col(q) = Column(basis_[q]);
      lu_.compute(B_);
      std::fill(in_basis_.begin(), in_basis_.end(), 0);
      for (int q = 0; q < d_; ++q)
        if (basis_[q] < n_) in_basis_[basis_[q]] = 1;
      int best = -1;
      double best_value = 1e-9;
      for (int k = 0; k < n_; ++k) {
        if (in_basis_[k]) continue;
        w_ = lu_.solve(Column(k));
        const double v = std::abs(w_(i));
        if (v > best_value) {
          best_value = v;
          best = k;
        }
      }
      if (best >= 0) basis_[i] = best;  // a redundant row keeps its artificial (harmless)
    }
  }

  // Starts from the basis of these columns of M instead of the artificial one: true when they are
  // d distinct columns whose basis is nonsingular and feasible (B^-1 r >= 0 to rounding).
  bool Start(const std::vector<int>& columns) {
    if (static_cast<int>(columns.size()) != d_) return false;
    std::fill(in_basis_.begin(), in_basis_.end(), 0);
    for (int k : columns) {
      if (k < 0 || k >= n_ || in_basis_[static_cast<std::size_t>(k)]) return false;
      in_basis_[static_cast<std::size_t>(k)] = 1;
    }
    for (int i = 0; i < d_; ++i) B_.col(i) = M_.col(columns[static_cast<std::size_t>(i)]);
    lu_.compute(B_);
    // A pivot of 1e-12 of the basis's scale: singular for these order-one programs.
    const double pivot = lu_.matrixLU().diagonal().cwiseAbs().minCoeff();
    if (!(pivot > 1e-12 * (1.0 + B_.cwiseAbs().maxCoeff()))) return false;
    xb_ = lu_.solve(r_);
    if (!(xb_.minCoeff() >= -1e-9 * (1.0 + r_.lpNorm<Eigen::Infinity>()))) return false;
    basis_ = columns;
    return true;
  }

  // The basis's columns of M, or nothing where an artificial one is in it.
  std::vector<int> RealBasis() const {
    for (int k : basis_) {
      if (k >= n_) return {};
    }
    return basis_;
  }

  const Eigen::VectorXd& pi() const { return pi_; }
  int d() const { return d_; }
  int n() const { return n_; }

 private:
  const Eigen::MatrixXd& M_;
  const Eigen::VectorXd& r_;
  int d_ = 0;
  int n_ = 0;
  std::vector<int> basis_;
  Eigen::VectorXd pi_;
  Eigen::VectorXd reduced_;
  // Each pivot's work, sized in the constructor.
  Eigen::MatrixXd B_;
  Eigen::VectorXd cb_, xb_, w_, column_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  std::vector<char> in_basis_;
};

}  // namespace

LinearProgramResult MinimiseLinearProgram(const Eigen::VectorXd& c, const Eigen::MatrixXd& A,
                                          const Eigen::VectorXd& b) {
  return MinimiseLinearProgram(c, A, b, nullptr);
}

LinearProgramResult MinimiseLinearProgram(const Eigen::VectorXd& c, const Eigen::MatrixXd& A,
                                          const Eigen::VectorXd& b, std::vector<int>* basis) {
  const int d = static_cast<int>(c.size());
  const int n = static_cast<int>(A.rows());
  if (A.cols() != d || b.size() != n || d == 0) {
    throw std::invalid_argument("linear program: inconsistent dimensions");
  }
  // Dual in standard form; rows with a negative right-hand side are negated so that the
  // artificial basis starts feasible. sign(i) records it: the primal x is sign .* pi.
  Eigen::MatrixXd M = A.transpose();
  Eigen::VectorXd r = -c;
  Eigen::VectorXd sign = Eigen::VectorXd::Ones(d);
  for (int i = 0; i < d; ++i) {
    if (r(i) < 0.0) {
      r(i) = -r(i);
      M.row(i) *= -1.0;
      sign(i) = -1.0;
    }
  }
  DualSimplex simplex(M, r);
  LinearProgramResult result;
  if (basis == nullptr || !simplex.Start(*basis)) {
    Eigen::VectorXd phase1 = Eigen::VectorXd::Zero(n + d);
    phase1.tail(d).setOnes();
    if (!simplex.Run(phase1, true, &result.iterations)) {
      throw std::runtime_error("linear program: phase 1 unbounded (internal error)");
    }
    // Phase-1 optimum: sum of artificials = r . pi.
    if (r.dot(simplex.pi()) > 1e-9 * (1.0 + r.lpNorm<Eigen::Infinity>())) {
      throw std::runtime_error("linear program: the primal is unbounded (dual infeasible)");
    }
    simplex.DriveOutArtificials();
  }
  Eigen::VectorXd phase2(n + d);
  phase2.head(n) = b;
  phase2.tail(d).setZero();
  if (!simplex.Run(phase2, false, &result.iterations)) {
    throw std::runtime_error("linear program: the primal constraints are infeasible");
  }
  result.x = sign.cwiseProduct(simplex.pi());
  result.objective = c.dot(result.x);
  if (basis != nullptr) *basis = simplex.RealBasis();
  return result;
}

}  // namespace fitfeel::metrology
