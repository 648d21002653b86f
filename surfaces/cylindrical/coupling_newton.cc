#include "surfaces/cylindrical/coupling_newton.h"

#include <algorithm>
#include <cassert>
#include <utility>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/LU>

#include "surfaces/cylindrical/elastic/column_sums.h"

namespace fitfeel::cylindrical {
namespace {
class CouplingOperator;
}  // namespace
}  // namespace fitfeel::cylindrical

// Eigen's matrix-free interface: the operator behaves as a sparse matrix times dense vectors.
namespace Eigen::internal {
template <>
struct traits<fitfeel::cylindrical::CouplingOperator>
    : public Eigen::internal::traits<Eigen::SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace fitfeel::cylindrical {
namespace {

class CouplingOperator : public Eigen::EigenBase<CouplingOperator> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };
  explicit CouplingOperator(const CouplingSystem* system) : system_(system) {}
  Eigen::Index rows() const { return system_->size(); }
  Eigen::Index cols() const { return system_->size(); }
  const CouplingSystem& system() const { return *system_; }
  template <typename Rhs>
  Eigen::Product<CouplingOperator, Rhs, Eigen::AliasFreeProduct> operator*(
      const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<CouplingOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

 private:
  const CouplingSystem* system_;
};

// Each component's diagonal block, factored (Eigen's preconditioner interface).
class ComponentBlocks {
 public:
  ComponentBlocks() = default;
  template <typename Matrix>
  explicit ComponentBlocks(const Matrix& a) {
    compute(a);
  }
  ComponentBlocks& analyzePattern(const CouplingOperator&) { return *this; }
  ComponentBlocks& factorize(const CouplingOperator& a) {
    const CouplingSystem& system = a.system();
    size_ = system.sections();
    lu_.clear();
    for (Eigen::Index c = 0; c < system.components(); ++c) {
      lu_.emplace_back(system.DiagonalBlock(c));
    }
    return *this;
  }
  ComponentBlocks& compute(const CouplingOperator& a) { return factorize(a); }
  template <typename Rhs>
  Eigen::VectorXd solve(const Rhs& b) const {
    Eigen::VectorXd x(b.size());
    for (std::size_t k = 0; k < lu_.size(); ++k) {
      const Eigen::Index at = static_cast<Eigen::Index>(k) * size_;
      x.segment(at, size_) = lu_[k].solve(b.segment(at, size_));
    }
    return x;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  Eigen::Index size_ = 0;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> lu_;
};

}  // namespace
}  // namespace fitfeel::cylindrical

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<fitfeel::cylindrical::CouplingOperator, Rhs, SparseShape, DenseShape,
                            GemvProduct>
    : generic_product_impl_base<fitfeel::cylindrical::CouplingOperator, Rhs,
                                generic_product_impl<fitfeel::cylindrical::CouplingOperator, Rhs>> {
  using Scalar = typename Product<fitfeel::cylindrical::CouplingOperator, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const fitfeel::cylindrical::CouplingOperator& lhs,
                            const Rhs& rhs, const Scalar& alpha) {
    Eigen::VectorXd y;
    lhs.system().Apply(rhs, &y);
    dst += alpha * y;
  }
};
}  // namespace Eigen::internal

namespace fitfeel::cylindrical {

void CouplingSystem::Reset(Eigen::Index sections, std::vector<int> component_mode) {
  sections_ = sections;
  component_mode_ = std::move(component_mode);
  int modes = 0;
  for (int mode : component_mode_) modes = std::max(modes, mode + 1);
  coupling_.resize(static_cast<std::size_t>(modes));
  response_.resize(static_cast<std::size_t>(sections));
  for (Eigen::MatrixXd& r : response_) r.setZero(components(), components());
  out_.resize(0, 0);
  in_.resize(0, 0);
}

Eigen::MatrixXd& CouplingSystem::mode_coupling(int mode) {
  return coupling_[static_cast<std::size_t>(mode)];
}

Eigen::MatrixXd& CouplingSystem::response(Eigen::Index section) {
  return response_[static_cast<std::size_t>(section)];
}

void CouplingSystem::PoseCoupled() {
  const Eigen::Index m = sections_;
  for (Eigen::Index c = 0; c < components(); ++c) {
    out_.middleRows(c * m, m) =
        coupling_[static_cast<std::size_t>(component_mode_[static_cast<std::size_t>(c)])] *
        out_.middleRows(c * m, m);
  }
}

void CouplingSystem::Apply(const Eigen::VectorXd& x, Eigen::VectorXd* y) const {
  const Eigen::Index m = sections_, nc = components();
  // z = diag(response) x, section by section, then y = x + M z component by component; the
  // products' sums in Eigen's order (TimesInOrder), into buffers kept between calls.
  Eigen::VectorXd& z = apply_z_;
  Eigen::VectorXd& xs = apply_xs_;
  Eigen::VectorXd& zs = apply_zs_;
  z.resize(size());
  xs.resize(nc);
  zs.resize(std::max(nc, m));
  for (Eigen::Index s = 0; s < m; ++s) {
    for (Eigen::Index c = 0; c < nc; ++c) xs[c] = x[c * m + s];
    TimesInOrder(response_[static_cast<std::size_t>(s)], xs.data(), zs.data());
    for (Eigen::Index c = 0; c < nc; ++c) z[c * m + s] = zs[c];
  }
  *y = x;
  for (Eigen::Index c = 0; c < nc; ++c) {
    TimesInOrder(coupling_[static_cast<std::size_t>(component_mode_[static_cast<std::size_t>(c)])],
                 z.data() + c * m, zs.data());
    y->segment(c * m, m) += zs.head(m);
  }
  if (out_.size() > 0) y->noalias() -= out_ * (in_ * x);
}

Eigen::MatrixXd CouplingSystem::DiagonalBlock(Eigen::Index component) const {
  const Eigen::Index m = sections_;
  Eigen::VectorXd own(m);
  for (Eigen::Index s = 0; s < m; ++s) {
    own[s] = response_[static_cast<std::size_t>(s)](component, component);
  }
  Eigen::MatrixXd block =
      coupling_[static_cast<std::size_t>(component_mode_[static_cast<std::size_t>(component)])] *
      own.asDiagonal();
  block.diagonal().array() += 1.0;
  if (out_.size() > 0) {
    block.noalias() -= out_.middleRows(component * m, m) * in_.middleCols(component * m, m);
  }
  return block;
}

Eigen::MatrixXd CouplingSystem::Dense() const {
  Eigen::MatrixXd a(size(), size());
  Eigen::VectorXd e = Eigen::VectorXd::Zero(size()), y;
  for (Eigen::Index k = 0; k < size(); ++k) {
    e[k] = 1.0;
    Apply(e, &y);
    a.col(k) = y;
    e[k] = 0.0;
  }
  return a;
}

Eigen::VectorXd CouplingSystem::Solve(const Eigen::VectorXd& rhs, double relative) const {
  const CouplingOperator op(this);
  Eigen::BiCGSTAB<CouplingOperator, ComponentBlocks> solver;
  solver.setTolerance(relative);
  solver.setMaxIterations(100);
  solver.compute(op);
  Eigen::VectorXd x = solver.solve(rhs);
  if (solver.info() == Eigen::Success) return x;
  return Dense().partialPivLu().solve(rhs);
}

}  // namespace fitfeel::cylindrical
