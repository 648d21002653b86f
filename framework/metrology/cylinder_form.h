#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel::metrology {

// A nominally cylindrical surface about the y axis sampled on a grid: row i at axial position
// y(i), column j at direction angle theta(j) in the (x, z) plane measured from x towards z, and
// the radial deviation deviation(i, j) of the surface from the nominal radius there. The sampled
// point is (R + v) * (cos theta, sin theta) at height y. This is exactly how a skin model shape
// stores a cylinder (paper Fig. 2), so evaluations run on the model's own points.
struct FITFEEL_API CylinderSamples {
  double nominal_radius = 0.0;  // m
  Eigen::VectorXd y;            // m (rows)
  Eigen::VectorXd theta;        // rad (columns)
  Eigen::MatrixXd deviation;    // m (rows x columns)

  Eigen::Matrix2Xd SectionPoints(int row) const;  // Cartesian (x, z) of one row
  // (cos theta, sin theta) of every column, and one row's points from them: a caller taking many
  // rows evaluates the columns' cosines and sines once (the same points, bit for bit).
  Eigen::Matrix2Xd Directions() const;
  Eigen::Matrix2Xd SectionPoints(int row, const Eigen::Matrix2Xd& directions) const;
};

struct CylindricityResult {
  double value = 0.0;  // radial width of the minimum zone, m
  // Zone axis: x = x0 + tx * y, z = z0 + tz * y.
  double x0 = 0.0, tx = 0.0, z0 = 0.0, tz = 0.0;
};

// Minimum-zone cylindricity (ISO 12180-1 MZCY, the ISO default), linearised about the nominal
// axis: the radial deviation seen from an axis (x0 + tx y, z0 + tz y) is v - (x0 + tx y) cos theta
// - (z0 + tz y) sin theta to first order, and the zone width is minimised exactly as a 6-variable
// linear program. The linearisation error is about e^2/(2R) for an axis displaced or tilted by e
// at a section (1e-9 m for e = 5 um on a 20 mm shaft): fine for skin model shapes, whose axis
// deviations are micrometres; not for gross misalignment.
FITFEEL_API CylindricityResult MinimumZoneCylindricity(const CylinderSamples& samples);

// Least-squares (geometric, Gauss-Newton) circle centre of each row: the extracted median line of
// ISO 12180-1 / ISO 17450-3 for a cylinder. Columns: (x, z) per row.
FITFEEL_API Eigen::Matrix2Xd SectionCentres(const CylinderSamples& samples);

// Straightness of a derived axis (ISO 12780-1 for a median line, cylindrical tolerance zone,
// minimum zone): the diameter of the smallest cylinder, of any position and direction, that
// contains every section centre (x(i), z(i)) at height y(i). Solved as the convex program it is
// (minimum enclosing cylinder, linearised in the axis tilt) by cutting planes over exact linear
// programs until the lower and upper bounds agree to 1e-9; the value returned is the exact
// diameter about the best axis found (an upper bound of the minimum). Fewer than three centres: 0.
FITFEEL_API double AxisStraightness(const Eigen::VectorXd& y, const Eigen::Matrix2Xd& centres);

// Minimum-zone straightness of a 2-D profile (ISO 12780-1 MZLI): the minimum width of the convex
// hull of the points (rotating calipers over hull edges), exact. Points: (position, height).
FITFEEL_API double ProfileStraightness(const Eigen::Matrix2Xd& points);

struct SizeRange {
  double min = 0.0;  // smallest local size minus nominal size, m
  double max = 0.0;  // largest
};

// Two-point sizes (ISO 14405-1 LP, the default size criterion since ISO 14405-1:2010): every
// diametrically opposite pair of sampled points, as deviations of the local diameter from the
// nominal one: v(i, j) + v(i, j + n/2). Needs an even column count with theta(j + n/2) =
// theta(j) + pi; throws std::invalid_argument otherwise.
FITFEEL_API SizeRange TwoPointSizes(const CylinderSamples& samples);

// The grid and per-cell radial deviations of a cylindrical skin model shape as samples.
FITFEEL_API CylinderSamples SamplesFromGrid(double nominal_radius, const SurfaceGrid& grid,
                                            const Eigen::VectorXd& deviation);

// One form characteristic of a cylinder (roundness: the worst section; generatrix straightness:
// the worst column, as a 2-D profile (y, v); axis straightness: least-squares section centres in a
// minimum cylinder; cylindricity: minimum zone). Throws std::invalid_argument for a characteristic
// a cylinder does not have.
FITFEEL_API double EvaluateCylinderForm(FormCharacteristic characteristic,
                                        const CylinderSamples& samples);

}  // namespace fitfeel::metrology
