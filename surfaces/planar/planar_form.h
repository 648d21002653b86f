#pragma once

#include <vector>

namespace fitfeel::planar {

// Minimum-zone evaluation (the ISO 12780 / 12781 default) of the form of flat faces, on the
// variation V of a skin model shape: a face's points are (y, z, V) with V normal to the face.

// Straightness of a line profile (t_k, v_k): the width, along v, of the narrowest pair of
// parallel lines enclosing the points, and the lines' slope. Exact: the minimum of the convex
// piecewise-linear width over the slope lies at the slope of an edge of the points' convex hull.
// One distinct t gives the range of v (no line can remove a spread at one abscissa).
struct LineZone {
  double width = 0.0;
  double slope = 0.0;
};
LineZone MinZoneStraightness(const std::vector<double>& t, const std::vector<double>& v);

// Flatness of a face sampled at (y_k, z_k, v_k): the narrowest pair of parallel planes
// v = a y + c z + q enclosing the points. The width is convex in (a, c); for each a the best c is
// the exact straightness above, and the convex function of a that remains is minimised by golden
// section to below 1e-20 of the face's range (far below the 0.1 nm any check resolves).
struct PlaneZone {
  double width = 0.0;
  double slope_y = 0.0;
  double slope_z = 0.0;
};
PlaneZone MinZoneFlatness(const std::vector<double>& y, const std::vector<double>& z,
                          const std::vector<double>& v);

// Range of v - a y - c z: the width of the zone of planes with the given slopes.
double RangeAlong(const std::vector<double>& y, const std::vector<double>& z,
                  const std::vector<double>& v, double a, double c);

}  // namespace fitfeel::planar
