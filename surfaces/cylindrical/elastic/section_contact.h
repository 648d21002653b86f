#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "surfaces/cylindrical/elastic/dense_cholesky.h"
#include "surfaces/cylindrical/elastic/harmonic_compliance.h"

namespace fitfeel::cylindrical {

// Unilateral (non-negative pressure) contact of one press-fit cross-section on n equally spaced
// columns, with the interface compliance per circumferential harmonic (harmonic_compliance.h).
// The compliance is circulant: the closure at column i from a pressure at column j depends only on
// i - j, g(m) = (1/n) sum_k C_k cos(2 pi k m / n). Given the rigid interference delta_j (positive
// where the undeformed surfaces overlap), finds p >= 0 with closure G p >= delta and
// p_j (G p - delta)_j = 0: the minimum of 1/2 p'Gp - delta'p over p >= 0, a linear
// complementarity problem with a symmetric positive definite matrix, solved exactly (to rounding)
// by block principal pivoting (Judice and Pires 1994) with Murty's single-pivot rule as the
// fallback that guarantees termination. Prepare-time only: it allocates.
class CirculantContact {
 public:
  // The factorizations of one section, kept between solves: a section whose contact set has not
  // changed since its last solve (the usual case late in a Newton search) solves with them in
  // O(n m), and one whose set changed by a few columns updates them by rows in O(n m) per column
  // instead of factoring anew. One per section; Solve uses its own without one.
  struct Factorization {
    // The columns of one factor, in the factor's order, and whether it is current.
    struct Factor {
      DenseCholesky cholesky;
      std::vector<int> columns;
      bool valid = false;
    };
    std::vector<int> index, gaps;  // the contact set F and the gaps N of the last step
    bool dual = false;             // solved on N with (G^-1)_NN (dual), else on F with G_FF
    bool last_full = false;        // the last solve was full contact (closed form)
    Factor primal, dual_factor;    // of G_FF and of (G^-1)_NN
    std::vector<char> mark;        // scratch: membership flags for the update
    void Invalidate() { primal.valid = dual_factor.valid = false; }
  };

  // compliance[k] for k = 0 .. n/2 (m/Pa); n even >= 4.
  CirculantContact(const std::vector<double>& compliance, int n);

  int columns() const { return n_; }
  const Eigen::MatrixXd& matrix() const { return g_; }
  // Solves the LCP for delta (n values). `active` (n flags) is the warm start on entry and the
  // contact set on exit. Returns the number of pivoting steps; throws if it fails to terminate.
  // `full`, when given, is G^-1 delta (every pressure of full contact, some negative: the caller
  // has tried SolveFull; it may be p itself, read before p is written); otherwise Solve computes it
  // and returns at once if it is feasible.
  int Solve(const double* delta, double* p, std::vector<char>* active, const double* full = nullptr,
            Factorization* workspace = nullptr);
  // The closed form of full contact for delta = U e - gap (U the columns' unit vectors) from
  // inverse_gap = G^-1 gap (InverseTimes): p = (G^-1 U) e - G^-1 gap, O(n) instead of O(n^2), so a
  // Newton search that moves e over fixed gaps pays the n^2 product once. p receives G^-1 delta
  // in every case; returns false when a pressure is negative (Solve takes it from there), and on
  // success sets every flag of `active`, as Solve does.
  bool SolveFull(const Eigen::Vector2d& e, const double* inverse_gap, double* p,
                 std::vector<char>* active, Factorization* workspace = nullptr);
  // out = G^-1 x (n values each).
  void InverseTimes(const double* x, double* out) const;
  // G^-1 1: what a uniform unit gap adds to InverseTimes (the breathing mode alone).
  const Eigen::VectorXd& inverse_ones() const { return inverse_ones_; }
  // After Solve: d(sum_j p_j u_j)/d(offset), the section's 2x2 radial contact stiffness per unit
  // cell area (Pa/m), for the rigid-body Newton step.
  Eigen::Matrix2d OffsetStiffness() const;
  // The same for gap shifts along the columns of `basis` (n x k) at a fixed offset, after a solve
  // with the workspace `ws`: d(B^T p)/d(shift) = -B_F^T G_FF^-1 B_F (k x k, Pa/m), F the contact
  // set. `inverse_basis` = G^-1 B, `full` = B^T G^-1 B (the answer in contact all round).
  Eigen::MatrixXd ShiftStiffness(const Factorization& ws, const Eigen::MatrixXd& basis,
                                 const Eigen::MatrixXd& inverse_basis,
                                 const Eigen::MatrixXd& full) const;

 private:
  int n_;
  Eigen::MatrixXd g_;
  std::vector<double> cos_, sin_;
  // Makes `factor` factor the principal submatrix a(target, target), by row updates from the
  // set it holds when few columns differ, else anew; `target` receives the factor's order.
  void Refactor(const Eigen::MatrixXd& a, std::vector<int>* target, Factorization::Factor* factor,
                std::vector<char>* mark) const;

  // Full contact has a closed form, p = G^-1 delta (tried first: it is the common case of a press
  // fit), with a constant offset stiffness.
  Eigen::MatrixXd g_inv_;
  Eigen::MatrixX2d g_inv_u_;  // G^-1 U
  Eigen::VectorXd inverse_ones_;
  Eigen::Matrix2d full_stiffness_;
  Eigen::VectorXd full_;
  Eigen::VectorXd w_, z_, sum_, coeff_;  // Solve's scratch: closures, dual unknowns, products
  Factorization own_;                    // without a caller's workspace
  // The last solve's workspace, for OffsetStiffness; null: own_. A copy of this object made
  // between a solve and its OffsetStiffness would point at the original's; nobody does that.
  const Factorization* last_ = nullptr;
};

// One cross-section (slice) of the engaged length for the rigid-body problem.
struct ContactSection {
  const double* gap = nullptr;  // rigid gap per column (S_T), m; positive = clearance
  double cell_area = 0.0;       // area of one column's cell in this slice, m^2
  double y = 0.0;               // axial position of the slice from the reference point, m
  // Optional warm start: the contact set (one flag per column) this section is expected to have,
  // e.g. that of the same bore row one depth step earlier. Only speed depends on it.
  const char* warm_contact = nullptr;
  // Optional, kept by the caller between solves (e.g. per bore row over the depth steps): the
  // factorizations of the section's contact set. They depend only on the set (the compliance is
  // the solver's), so any earlier ones are valid starting points. Null: the solver's own, new
  // for each Solve.
  CirculantContact::Factorization* factorization = nullptr;
};

// How the moving part may move against the fixed one, and what holds it.
struct RigidFreedom {
  bool tilt = false;                 // 4 DOF (offset and tilt) instead of 2 (offset)
  double tilt_stiffness = 0.0;       // holder's rotational stiffness, N*m/rad (0 = free)
  Eigen::Vector2d force{0.0, 0.0};   // external radial load on the part (x, z), N
  Eigen::Vector2d moment{0.0, 0.0};  // its first moment about the reference point, N*m
};

// A section's offset per step of the part's pose q = (offset, tilt): P = [I, y I] (2 x 4), or I
// (2 x 2) where the part may not tilt.
Eigen::MatrixXd SectionPlacement(const ContactSection& section, const RigidFreedom& freedom);

struct RigidContactResult {
  Eigen::Vector2d offset{0.0, 0.0};     // axis offset at the reference point, m
  Eigen::Vector2d tilt{0.0, 0.0};       // axis slope (dx/dy, dz/dy), rad
  double normal_force = 0.0;            // sum p * A, N
  Eigen::Vector2d resultant{0.0, 0.0};  // sum p * A * u_j, N
  double max_pressure = 0.0;            // Pa
  int newton_iterations = 0;
  // Whether the part is at equilibrium (the unbalanced force within the solve's tolerance); when
  // not (a Solve limited in Newton steps), `next` is the Newton step's point from the pose
  // returned, not evaluated (else the pose returned).
  bool converged = true;
  Eigen::Vector4d next = Eigen::Vector4d::Zero();
};

// The rigid part's equilibrium in offset (and tilt) against the elastic contact of every section:
// minimises the convex potential sum_s phi_s(e_s) - load . q (+ the holder's tilt energy) with
// e_s = offset + y_s tilt and phi_s the section's stored elastic energy at its LCP solution, by
// Newton's method with backtracking (the gradient is the unbalanced force, the Hessian the
// sections' contact stiffness). Each section deforms on its own (plane sections; the parts'
// deformation along their axes, order by order, is coupled by the caller, axial_coupling.h,
// through the sections' gaps: gap_shift, ShiftStiffness, ShiftFullContact). Prepare-time only.
class RigidSectionContact {
 public:
  // `shift_orders`: the circumferential orders (1 .. n_columns / 2) a caller's gap shifts may
  // carry besides the uniform one (Solve's `gap_shift`, ShiftFullContact).
  RigidSectionContact(const PressFitSection& section, int n_columns,
                      const std::vector<int>& shift_orders = {});

  int columns() const { return contact_.columns(); }
  // A gap shift's components as columns (n_columns x (1 + 2 orders)): 1, then cos(n theta_j) and
  // sin(n theta_j) for each shift order n, theta_j the columns' angles from column 0.
  const Eigen::MatrixXd& shift_basis() const { return shift_basis_; }
  const CirculantContact& contact() const { return contact_; }
  // Pressures of every section of the last Solve, section-major (Pa).
  const std::vector<double>& pressures() const { return pressure_; }
  // Contact set of every section of the last Solve (one flag per column), for warm starts.
  const std::vector<std::vector<char>>& contact_sets() const { return active_; }
  // After a Solve: the response of section s's pressures to its gap shift and to its offset
  // e_s, at the solve's contact set: with E = [shift_basis(), cos, sin] (the offset's
  // directions last), S = ShiftStiffness(s) = E_F^T G_FF^-1 E_F, and
  // d(E^T p_s) = S (-d shift; d e_s) (a section out of contact: zero).
  Eigen::MatrixXd ShiftStiffness(std::size_t section) const;
  // After a Solve that left every section in contact all round: the exact answer when the
  // gaps of section s grow by its shift components (section-major, shift_basis()'s columns; m).
  // All round the contact is linear, so the pressures move by -G^-1 B x_s, and the part's offset
  // and tilt (`freedom`'s) move to balance the net forces the shifts make (order 1's; a uniform or
  // order n >= 2 change has none and leaves the part where it was). Updates the result's pose,
  // normal force, resultant and largest pressure. Returns false, changing nothing, if a section
  // is not in contact all round or a pressure would turn negative.
  bool ShiftFullContact(std::span<const ContactSection> sections, const RigidFreedom& freedom,
                        std::span<const double> shift, RigidContactResult* result);

  // `gap_shift`, when given (shift_basis()'s components per section, section-major): the sections
  // are the last Solve's with the gaps of section s grown since by its components (the caller's
  // axial coupling), so that the products of the gaps it keeps are updated instead of computed
  // anew. `handoff` > 0: where the
  // unbalanced force falls below `handoff` times the forces the solve carries (but not yet to
  // its tolerance), the solve stops and returns the next Newton point unevaluated in `next`, for
  // an iteration that also moves the gaps (the axial coupling's) to take one evaluation per step
  // of both.
  RigidContactResult Solve(std::span<const ContactSection> sections, const RigidFreedom& freedom,
                           const Eigen::Vector4d& warm, std::span<const double> gap_shift = {},
                           double handoff = 0.0);

 private:
  // Potential, gradient and Hessian at q; leaves every section's pressures and contact set at q.
  double Evaluate(std::span<const ContactSection> sections, const RigidFreedom& freedom,
                  const Eigen::Vector4d& q, Eigen::Vector4d* grad, Eigen::Matrix4d* hess);

  // Step length along dir (4-vector in q) at which the first column touches; inf if none.
  double DistanceToContact(std::span<const ContactSection> sections, const RigidFreedom& freedom,
                           const Eigen::Vector4d& q, const Eigen::Vector4d& dir) const;

  // Moves the kept G^-1 gap of every section by its shift's components (section-major).
  void ShiftInverseGaps(std::span<const double> shift);
  // G^-1 gap of each section of the current Solve, computed when first needed.
  const double* InverseGap(const ContactSection& section, std::size_t index);

  CirculantContact contact_;
  Eigen::MatrixXd shift_basis_;                              // B
  Eigen::MatrixXd response_basis_, inverse_response_basis_;  // E = [B, cos, sin] and G^-1 E
  Eigen::MatrixXd full_response_;                            // E^T G^-1 E
  std::vector<double> cos_, sin_, delta_, pressure_, inverse_gap_, shifted_;
  std::vector<char> inverse_gap_ready_;
  std::vector<CirculantContact::Factorization> factors_;  // one per section of the current Solve
  // Per section of the last evaluation, the workspace its solve used (null: out of contact).
  std::vector<const CirculantContact::Factorization*> workspace_;
  std::vector<std::vector<char>> active_;
};

}  // namespace fitfeel::cylindrical
