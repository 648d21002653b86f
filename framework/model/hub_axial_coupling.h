#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/harmonic_compliance.h"

namespace fitfeel {

// What plane sections leave out of a hub's breathing (n = 0) mode: a thick-walled tube loaded
// over part of its length carries the load past the loaded part's end by bending along its axis,
// so it is stiffer there than its Lame sections say (CalculiX: a shaft half way into the paper's
// hub, 20 mm long with a 5 mm wall, meets 16 % more force than plane sections give;
// docs/contact-mechanics.md, section 6).
//
// The hub's mean radial displacement w(y) along its bore rows is that of an axisymmetric
// cylindrical shell on an elastic foundation (Timoshenko and Woinowsky-Krieger, Theory of Plates
// and Shells, 1959, section 114: D w'''' + E t / R^2 w = p), with the foundation taken as the
// hub's own Lame stiffness k = 1 / C_0,hub (per unit bore area; for a thick wall E t / R^2 is
// not it) and the shell's flexural rigidity D = E t^3 / (12 (1 - nu^2)) of the wall t = (d2 - d1)
// / 2 at its mid-radius R, referred to the bore (energy per radian: D R w''^2 against k a w^2, so
// D R / a w'''' + k w = p). Both faces are free. On rows of pitch h, by central differences of
// the bending energy:
//   K w = h p,   K = (D R / a) D2' D2 h + k h I   (D2 the second difference over h^2),
// and F = h K^-1 is the hub's displacement per unit mean row pressure. A uniform pressure over
// every row bends nothing: F p = p / k, the plane sections' answer. What the sections need is the
// difference, X = F - I / k: the extra displacement of each row's bore for the rows' mean
// pressures, added to the sections' gaps. Prepare-time only: it allocates.
class FITFEEL_API HubAxialCoupling {
 public:
  HubAxialCoupling() = default;
  // `rows` bore rows of pitch `row_pitch` (m) over the hub of `section` (its d1, d2, hub material
  // and plane_strain, as the sections' compliance takes them).
  HubAxialCoupling(const PressFitSection& section, double row_pitch, int rows);

  bool empty() const { return extra_.size() == 0; }
  int rows() const { return static_cast<int>(extra_.rows()); }
  // The hub's Lame breathing stiffness k, Pa/m, and its shell rigidity referred to the bore, N*m.
  double foundation() const { return foundation_; }
  double rigidity() const { return rigidity_; }
  // out[i] = sum_j X(i, j) mean_pressure[j] (rows() values each; pressures in Pa, out in m).
  void ExtraDisplacement(const double* mean_pressure, double* out) const;
  const Eigen::MatrixXd& matrix() const { return extra_; }

 private:
  Eigen::MatrixXd extra_;
  double foundation_ = 0.0;
  double rigidity_ = 0.0;
};

}  // namespace fitfeel
