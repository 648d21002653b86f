#pragma once

#include <algorithm>
#include <cmath>

#include "surfaces/cylindrical/elastic_options.h"

namespace fitfeel::cylindrical {

// What the elastic law's prepare costs at worst, every section in contact at every depth step (a
// press fit), for the loader's admission (SurfaceType::EstimatePrepareSeconds): per depth step the
// sections' coupled solve is a Newton iteration whose systems couple every row with every other
// in each coupled order, so
//     s = c * depth_steps * rows^2 * (1 + coupled orders) * sqrt(solve columns / 120).
// Measured with `fitfeel run` and one prepare thread on the two-core development machine,
// fits-20mm-h7n6 (120 depth steps at 40 rows, the grid's 360 columns solved in 120): 20 / 40 /
// 80 / 160 rows 0.34 / 1.37 / 6.24 / 100 s; at 40 rows, 60 / 120 / 240 solve columns 1.00 / 1.37 /
// 2.00 s and axial_orders 0 / 6 / 12 0.23 / 1.37 / 1.79 s. c = 8e-7 s gives 0.13 / 1.08 / 8.6 / 69
// s, 0.76 / 1.08 / 1.52 s and 0.15 / 1.08 / 2.0 s: within a factor of 1.5 from 40 rows up, and
// it crosses the admission's 30 s at 121 rows where the measured cost does at about 118 (at 20
// rows fixed costs dominate). A pair that never touches prepares in a fraction of it; the
// admission is for the worst case.
inline constexpr double kElasticSecondsPerRowStep = 8e-7;

inline double ElasticPrepareSeconds(const ElasticOptions& options, int rows, int columns,
                                    double depth_steps) {
  const int orders = options.axial_coupling ? options.axial_orders : 0;
  const double solve_columns = std::min(columns, options.columns);
  return kElasticSecondsPerRowStep * depth_steps * rows * rows * (1 + orders) *
         std::sqrt(solve_columns / ElasticOptions::kDefaultColumns);
}

}  // namespace fitfeel::cylindrical
