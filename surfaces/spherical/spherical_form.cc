#include "surfaces/spherical/spherical_form.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/metrology/circle_fit.h"
#include "framework/metrology/linear_program.h"
#include "surfaces/common/surface_of_revolution.h"

namespace fitfeel::spherical {
namespace {

double Roundness(const SphericalGeometry& geometry, const SurfaceGrid& grid,
                 const Eigen::VectorXd& deviation) {
  const double a = geometry.radius();
  double worst = 0.0;
  Eigen::Matrix2Xd points(2, grid.columns);
  for (int i = 0; i < grid.rows; ++i) {
    const double y = grid.row_position(i);
    const double cos_lat = std::sqrt(a * a - y * y) / a;
    for (int j = 0; j < grid.columns; ++j) {
      const double r = (a + deviation(grid.index(i, j))) * cos_lat;
      points(0, j) = r * std::cos(grid.column_angle(j));
      points(1, j) = r * std::sin(grid.column_angle(j));
    }
    worst = std::max(worst, metrology::MinimumZoneRoundness(points).value);
  }
  return worst;
}

double Sphericity(const SurfaceGrid& grid, const Eigen::VectorXd& deviation) {
  // Variables x = (c_x, c_y, c_z, r_in, r_out) in units of `scale` (the LP wants order one):
  //   r_in <= V_k - c.n_k <= r_out,  minimise r_out - r_in.
  const double scale = deviation.cwiseAbs().maxCoeff();
  const int cells = grid.size();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * cells, 5);
  Eigen::VectorXd b(2 * cells);
  for (int k = 0; k < cells; ++k) {
    const Eigen::Vector3d n = grid.normal.col(k);
    const double v = deviation(k) / scale;
    A.block<1, 3>(2 * k, 0) = -n.transpose();  // V - c.n <= r_out
    A(2 * k, 4) = -1.0;
    b(2 * k) = -v;
    A.block<1, 3>(2 * k + 1, 0) = n.transpose();  // r_in <= V - c.n
    A(2 * k + 1, 3) = 1.0;
    b(2 * k + 1) = v;
  }
  Eigen::VectorXd c(5);
  c << 0.0, 0.0, 0.0, -1.0, 1.0;
  const metrology::LinearProgramResult result = metrology::MinimiseLinearProgram(c, A, b);
  // The exact radial width about the centre found (an upper bound of the minimum, equal to it at
  // the optimum), rather than the LP's objective, so rounding can only overstate it.
  const Eigen::Vector3d centre = result.x.head<3>();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int k = 0; k < cells; ++k) {
    const double r = deviation(k) / scale - centre.dot(grid.normal.col(k));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return (hi - lo) * scale;
}

}  // namespace

double EvaluateSphereForm(FormCharacteristic characteristic, const SphericalGeometry& geometry,
                          const SurfaceGrid& grid, const Eigen::VectorXd& deviation) {
  // A zero deviation is exactly zero form: skip the fits, whose rounding would report ~1e-19 m.
  if (deviation.size() == 0 || deviation.cwiseAbs().maxCoeff() == 0.0) return 0.0;
  switch (characteristic) {
    case FormCharacteristic::kRoundness:
      return Roundness(geometry, grid, deviation);
    case FormCharacteristic::kSphericity:
      return Sphericity(grid, deviation);
    default:
      throw std::invalid_argument("a sphere has no " + ToString(characteristic) + " here");
  }
}

TwoPointRange TwoPointSizes(const SurfaceGrid& grid, const Eigen::VectorXd& deviation) {
  return revolution::TwoPointSizes(grid, deviation, revolution::Antipode::kMirroredRow);
}

std::vector<CharacteristicCheck> EvaluateSphereCharacteristics(const PartSpec& part,
                                                               const SkinModelShape& sms) {
  const SphericalGeometry& geometry = GeometryOf(part);
  return revolution::EvaluateCharacteristics(
      part, sms, revolution::Antipode::kMirroredRow,
      [&](FormCharacteristic characteristic, const Eigen::VectorXd& form) {
        return EvaluateSphereForm(characteristic, geometry, sms.grid, form);
      });
}

}  // namespace fitfeel::spherical
