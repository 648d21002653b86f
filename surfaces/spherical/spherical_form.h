#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"
#include "framework/model/surface_type.h"
#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {

// Form characteristics of a sampled spherical band; `deviation` is radial (from the centre), per
// cell, in metres.
// - roundness (ISO 12181-1, default MZCI): the worst row's minimum-zone radial width, each row
//   (a circle of latitude) evaluated in its own plane on the points (a + V) cos(latitude);
// - sphericity (minimum zone, as ISO 12181 does for a circle): the smallest radial separation of
//   two concentric spheres containing every point, linearised about the nominal centre (the
//   radial distance from a centre c is a + V - c.n to first order; the error is |c|^2/(2a), 1e-11 m
//   for a 1 um centre shift on a 29 mm ball) and solved exactly as a 5-variable linear program.
double EvaluateSphereForm(FormCharacteristic characteristic, const SphericalGeometry& geometry,
                          const SurfaceGrid& grid, const Eigen::VectorXd& deviation);

// Two-point sizes through the centre (ISO 14405-1 LP): cell (i, j) and its antipode
// (m-1-i, j+n/2), as the diameter deviation V + V_antipode.
using TwoPointRange = revolution::TwoPointRange;
TwoPointRange TwoPointSizes(const SurfaceGrid& grid, const Eigen::VectorXd& deviation);

// Every characteristic of `part`'s spec on a skin model shape: two-point sizes on the whole
// variation, form on the variation without the sampled texture.
std::vector<CharacteristicCheck> EvaluateSphereCharacteristics(const PartSpec& part,
                                                               const SkinModelShape& sms);

}  // namespace fitfeel::spherical
