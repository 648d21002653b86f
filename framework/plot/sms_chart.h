#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"
#include "framework/plot/figure.h"

namespace fitfeel::plot {

// Radial size limits of a part's skin variation V, m: V is a half-size quantity, so the limits are
// half the diametral deviations of the size specification (ei/2, es/2 or EI/2, ES/2).
struct RadialLimits {
  double lower = 0.0;
  double upper = 0.0;
};
FITFEEL_API RadialLimits VariationLimits(const PartSpec& part);
// Limits of the tolerance space S_T = V_outer - V_inner: from the smallest (EI - es)/2 to the
// largest (ES - ei)/2 radial clearance; negative values are interference.
FITFEEL_API RadialLimits ToleranceSpaceLimits(const PartSpec& inner, const PartSpec& outer);

// The unwrapped skin profile of one part (paper Fig. 6): axial position (mm) across, direction
// angle (degrees) up, colour = V (µm); the colour bar marks the size limits. Throws UserError for
// a shape whose grid and variation disagree.
FITFEEL_API HeatMap MakeSkinProfileMap(const PartSpec& part, const SkinModelShape& sms);

// The tolerance space over the overlapping cells at one pose, on a grid of rows (axial positions,
// m) by columns (direction angles, rad), values S_T in m.
struct ToleranceSpaceGrid {
  Eigen::VectorXd axial;
  Eigen::VectorXd angle;
  Eigen::MatrixXd value;  // axial.size() x angle.size()
};
FITFEEL_API HeatMap MakeToleranceSpaceMap(const PartSpec& inner, const PartSpec& outer,
                                          const ToleranceSpaceGrid& space,
                                          const std::string& where);

// A chart of the given part maps and, when present, the tolerance space map.
FITFEEL_API HeatMapChart MakeSmsChart(const std::string& scenario, std::vector<HeatMap> maps);

}  // namespace fitfeel::plot
