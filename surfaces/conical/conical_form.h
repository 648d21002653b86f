#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"
#include "framework/model/surface_type.h"
#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {

// Form characteristics of a sampled cone, evaluated as ISO GPS verification would, on the cone's
// own grid points (radius DiameterAt(row)/2 + deviation at angle column_angle):
// - roundness (ISO 12181-1, default MZCI): the worst row's minimum-zone radial width;
// - generatrix straightness (ISO 12780-1, default MZLI): the worst column's minimum-zone width of
//   the profile (axial position, deviation); the deviation is radial, which differs from the
//   deviation normal to the cone by the factor cos(alpha) (1 - 5e-5 at 1:50): below any tolerance;
// - axis straightness (ISO 12780-1 for a derived median line): the smallest cylinder containing
//   the least-squares centres of all rows.
// `deviation` is per cell (rows x columns as the grid stores it), in metres.
double EvaluateConeForm(FormCharacteristic characteristic, const ConicalGeometry& geometry,
                        const SurfaceGrid& grid, const Eigen::VectorXd& deviation);

// Smallest and largest two-point size deviation (ISO 14405-1 LP, the default): the diameter
// through opposite cells (j, j + n/2) of a row minus the nominal diameter there, i.e.
// V(i, j) + V(i, j + n/2). Needs an even column count.
using TwoPointRange = revolution::TwoPointRange;
TwoPointRange TwoPointSizes(const SurfaceGrid& grid, const Eigen::VectorXd& deviation);

// Every characteristic of `part`'s spec on a skin model shape: two-point size limits on the whole
// variation, each specified form tolerance on the variation without the sampled texture (ISO
// form evaluation filters out the short wavelengths of the texture).
std::vector<CharacteristicCheck> EvaluateConeCharacteristics(const PartSpec& part,
                                                             const SkinModelShape& sms);

}  // namespace fitfeel::conical
