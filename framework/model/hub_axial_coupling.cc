#include "framework/model/hub_axial_coupling.h"

#include <Eigen/Cholesky>

#include "framework/core/demand.h"
#include "framework/core/error.h"

namespace fitfeel {

HubAxialCoupling::HubAxialCoupling(const PressFitSection& section, double row_pitch, int rows) {
  if (!(section.d1 > 0.0) || !(section.d2 > section.d1)) {
    throw UserError("hub axial coupling needs 0 < d1 < d2");
  }
  if (!(row_pitch > 0.0) || rows < 1) {
    throw UserError("hub axial coupling needs a positive row pitch and at least one row");
  }
  if (!(section.hub.youngs_modulus > 0.0) || !(section.hub.poisson > -1.0) ||
      !(section.hub.poisson < 0.5)) {
    throw UserError("hub axial coupling needs the hub's Young's modulus and Poisson's ratio");
  }
  double e = section.hub.youngs_modulus, nu = section.hub.poisson;
  const double a = 0.5 * section.d1, b = 0.5 * section.d2;
  const double t = b - a, r = 0.5 * (a + b);
  const double shell = e * t * t * t / (12.0 * (1.0 - nu * nu));
  if (section.plane_strain) {  // the sections' own substitution, for their Lame term
    e /= 1.0 - nu * nu;
    nu /= 1.0 - nu;
  }
  foundation_ = e / (a * ((b * b + a * a) / (b * b - a * a) + nu));
  rigidity_ = shell * r / a;
  const auto m = static_cast<Eigen::Index>(rows);
  const double h = row_pitch;
  Eigen::MatrixXd k = Eigen::MatrixXd::Identity(m, m) * (foundation_ * h);
  // Bending energy (D/2) sum (w_{i-1} - 2 w_i + w_{i+1})^2 / h^4 * h over the interior rows; the
  // end rows have none of their own (free faces: no moment, no shear).
  const double c = rigidity_ / (h * h * h);
  const double stencil[3] = {1.0, -2.0, 1.0};
  for (Eigen::Index i = 1; i + 1 < m; ++i) {
    for (int u = 0; u < 3; ++u) {
      for (int v = 0; v < 3; ++v) k(i - 1 + u, i - 1 + v) += c * stencil[u] * stencil[v];
    }
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  FITFEEL_DEMAND(llt.info() == Eigen::Success);  // k h I plus a Gram matrix: definite
  extra_ = llt.solve(Eigen::MatrixXd::Identity(m, m) * h);
  extra_.diagonal().array() -= 1.0 / foundation_;
}

void HubAxialCoupling::ExtraDisplacement(const double* mean_pressure, double* out) const {
  Eigen::Map<Eigen::VectorXd>(out, extra_.rows()) =
      extra_ * Eigen::Map<const Eigen::VectorXd>(mean_pressure, extra_.cols());
}

}  // namespace fitfeel
