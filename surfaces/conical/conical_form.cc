#include "surfaces/conical/conical_form.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "framework/core/error.h"
#include "framework/metrology/circle_fit.h"
#include "framework/metrology/cylinder_form.h"
#include "surfaces/common/surface_of_revolution.h"

namespace fitfeel::conical {
namespace {

Eigen::Matrix2Xd RowPoints(const ConicalGeometry& geometry, const SurfaceGrid& grid,
                           const Eigen::VectorXd& deviation, int row) {
  const double radius = 0.5 * geometry.DiameterAt(grid.row_position(row));
  Eigen::Matrix2Xd points(2, grid.columns);
  for (int j = 0; j < grid.columns; ++j) {
    const double r = radius + deviation(grid.index(row, j));
    points(0, j) = r * std::cos(grid.column_angle(j));
    points(1, j) = r * std::sin(grid.column_angle(j));
  }
  return points;
}

}  // namespace

double EvaluateConeForm(FormCharacteristic characteristic, const ConicalGeometry& geometry,
                        const SurfaceGrid& grid, const Eigen::VectorXd& deviation) {
  // A zero deviation is exactly zero form: skip the fits, whose rounding would report ~1e-19 m.
  if (deviation.size() == 0 || deviation.cwiseAbs().maxCoeff() == 0.0) return 0.0;
  switch (characteristic) {
    case FormCharacteristic::kRoundness: {
      double worst = 0.0;
      for (int i = 0; i < grid.rows; ++i) {
        worst = std::max(
            worst, metrology::MinimumZoneRoundness(RowPoints(geometry, grid, deviation, i)).value);
      }
      return worst;
    }
    case FormCharacteristic::kGeneratrixStraightness: {
      double worst = 0.0;
      Eigen::Matrix2Xd profile(2, grid.rows);
      for (int j = 0; j < grid.columns; ++j) {
        for (int i = 0; i < grid.rows; ++i) {
          profile(0, i) = grid.row_position(i);
          profile(1, i) = deviation(grid.index(i, j));
        }
        worst = std::max(worst, metrology::ProfileStraightness(profile));
      }
      return worst;
    }
    case FormCharacteristic::kAxisStraightness: {
      Eigen::Matrix2Xd centres(2, grid.rows);
      for (int i = 0; i < grid.rows; ++i) {
        centres.col(i) =
            metrology::LeastSquaresCircle(RowPoints(geometry, grid, deviation, i)).centre;
      }
      return metrology::AxisStraightness(grid.row_position, centres);
    }
    default:
      throw std::invalid_argument("a cone has no " + ToString(characteristic) + " here");
  }
}

TwoPointRange TwoPointSizes(const SurfaceGrid& grid, const Eigen::VectorXd& deviation) {
  return revolution::TwoPointSizes(grid, deviation, revolution::Antipode::kSameRow);
}

std::vector<CharacteristicCheck> EvaluateConeCharacteristics(const PartSpec& part,
                                                             const SkinModelShape& sms) {
  const ConicalGeometry& geometry = GeometryOf(part);
  return revolution::EvaluateCharacteristics(
      part, sms, revolution::Antipode::kSameRow,
      [&](FormCharacteristic characteristic, const Eigen::VectorXd& form) {
        return EvaluateConeForm(characteristic, geometry, sms.grid, form);
      });
}

}  // namespace fitfeel::conical
