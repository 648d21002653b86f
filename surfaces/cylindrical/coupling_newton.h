#pragma once

#include <vector>

#include <Eigen/Core>

namespace fitfeel::cylindrical {

// The Newton system of the parts' axial coupling, (I - M J) dx = rhs, over the sections' shift
// components (component-major: component c of section s at c * sections + s). M is block diagonal
// by component, each block the coupling of the component's mode between sections; J is each
// section's response of its pressure amplitudes to its own shift (a small block per section)
// less the part's rigid answer, a term of rank 2 or 4: I - M J = I + M diag(response) - out in.
// Held in that form, a product costs components * sections^2 instead of (components *
// sections)^2, and the system is solved by BiCGSTAB preconditioned with each component's own
// block (exact where every section is in contact all round; measured: 1 to 12 % residual left on
// a press fit, where the dense factorization of the whole was most of the prepare).
// Prepare-time only: it allocates.
class CouplingSystem {
 public:
  // Clears the system for `sections` sections and `component_mode.size()` components, component c
  // of mode component_mode[c].
  void Reset(Eigen::Index sections, std::vector<int> component_mode);

  Eigen::Index sections() const { return sections_; }
  Eigen::Index size() const { return sections_ * components(); }
  Eigen::Index components() const { return static_cast<Eigen::Index>(component_mode_.size()); }
  // The coupling of mode k between sections (sections x sections), to be filled.
  Eigen::MatrixXd& mode_coupling(int mode);
  // Section s's response block: d(amplitudes)/d(shift) at a fixed pose, negated (components x
  // components), to be filled.
  Eigen::MatrixXd& response(Eigen::Index section);
  // The rigid answer's factors, size() x k and k x size(): the system loses out * in. `out`
  // is given as the sections' amplitude change per pose step; PoseCoupled() applies M to it.
  Eigen::MatrixXd& pose_out() { return out_; }
  Eigen::MatrixXd& pose_in() { return in_; }
  void PoseCoupled();

  // y = (I - M J) x.
  void Apply(const Eigen::VectorXd& x, Eigen::VectorXd* y) const;
  // The system's diagonal block of component c (sections x sections).
  Eigen::MatrixXd DiagonalBlock(Eigen::Index component) const;
  // The whole system, dense: for checks and for the fallback.
  Eigen::MatrixXd Dense() const;
  // dx for `rhs`, to a residual of `relative` times |rhs|.
  Eigen::VectorXd Solve(const Eigen::VectorXd& rhs, double relative) const;

 private:
  Eigen::Index sections_ = 0;
  std::vector<int> component_mode_;
  std::vector<Eigen::MatrixXd> coupling_;  // per mode
  std::vector<Eigen::MatrixXd> response_;  // per section
  Eigen::MatrixXd out_, in_;
  // Apply's buffers (the system is one thread's, as its callers' scratch is).
  mutable Eigen::VectorXd apply_z_, apply_xs_, apply_zs_;
};

}  // namespace fitfeel::cylindrical
