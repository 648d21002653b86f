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

// The vertical axis of an unwrapped map of a grid whose columns have direction angles `angles`
// (rad): angles in degrees for a surface of revolution (they increase around it), column numbers
// (label "column (face by face)") otherwise, since a flat face's columns share its normal's angle,
// one face after the other. Sets the map's y, y_label and y_tic_step.
FITFEEL_API void SetColumnAxis(const Eigen::VectorXd& angles, HeatMap* map);

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
// Axial extent of a grid's rows: boundaries halfway between row centres, the end rows as wide as
// their neighbours' spacing. Needs two rows or more.
FITFEEL_API double MatingLength(const SurfaceGrid& grid);

// Depth at which the mating surfaces first overlap completely: the shorter one's length.
FITFEEL_API double FullInsertionDepth(const SkinModelShape& inner, const SkinModelShape& outer);

// The tolerance space S_T = V_outer - V_inner at insertion depth `depth` (m), with the alignment of
// the contact analyzers (framework/model/contact_analyzer.h, MatingPose): depth 0 puts the inner
// part's leading end (its largest axial coordinate) at the outer part's entrance (its smallest),
// and at depth D an inner point s behind its leading end faces the outer surface D - s past the
// entrance. Cells are piecewise constant; the overlap is sampled at `samples_per_row` evenly
// spaced positions per row of the finer grid there, so every slice between row boundaries shows.
// Axial positions of the result are measured from the outer part's entrance. Each inner column
// faces the outer column nearest in angle. Throws UserError when the surfaces do not overlap.
FITFEEL_API ToleranceSpaceGrid ToleranceSpaceAtDepth(const SkinModelShape& inner,
                                                     const SkinModelShape& outer, double depth,
                                                     int samples_per_row = 4);

FITFEEL_API HeatMap MakeToleranceSpaceMap(const PartSpec& inner, const PartSpec& outer,
                                          const ToleranceSpaceGrid& space,
                                          const std::string& where);

// A chart of the given part maps and, when present, the tolerance space map.
FITFEEL_API HeatMapChart MakeSmsChart(const std::string& scenario, std::vector<HeatMap> maps);

}  // namespace fitfeel::plot
