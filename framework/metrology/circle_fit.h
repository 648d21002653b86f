#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel::metrology {

struct Circle {
  Eigen::Vector2d centre{0.0, 0.0};
  double radius = 0.0;
};

// Geometric least-squares circle (ISO 12181 LSCI): minimises the sum of squared distances of the
// points from the circle, by Gauss-Newton started from the algebraic (Kasa) fit. The algebraic fit
// alone is biased on partial arcs and noisy data, so it is only the start. Needs >= 3 points not
// all on one line; throws std::invalid_argument otherwise.
FITFEEL_API Circle LeastSquaresCircle(const Eigen::Matrix2Xd& points);

struct RoundnessResult {
  double value = 0.0;  // radial width of the minimum zone, m
  Eigen::Vector2d centre{0.0, 0.0};
  double inner_radius = 0.0;
  double outer_radius = 0.0;
};

// Minimum-zone roundness (ISO 12181-1 MZCI, the ISO default): the smallest radial separation of
// two concentric circles enclosing the points. Each step solves the limacon linearisation about the
// current centre exactly, a Chebyshev fit of (centre shift, mean radius) found by Remez's exchange
// on four points (the 4-variable linear program it is, over a working set of the points, where the
// exchange meets a degenerate reference), then recentres and recomputes the polar coordinates;
// the linearisation error is e^2/(2R) for a centre shift e, so a few steps converge to rounding.
// The value returned is the exact radial width of the points about the final centre (an upper
// bound of the minimum zone, equal to it at convergence). Needs >= 4 points.
FITFEEL_API RoundnessResult MinimumZoneRoundness(const Eigen::Matrix2Xd& points);

}  // namespace fitfeel::metrology
