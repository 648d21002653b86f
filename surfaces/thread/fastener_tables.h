#pragma once

#include <span>

namespace fitfeel::thread {

// ISO 273 clearance hole series for bolts.
enum class ClearanceSeries { kFine, kMedium, kCoarse };

// Dimensions of an ISO metric coarse-pitch bolt, its nut and its clearance hole, in metres:
//  - thread: nominal diameter d and the ISO 261 coarse pitch P;
//  - hexagon head, ISO 4014 / ISO 4017: width across flats s, nominal head height k and the
//    minimum bearing face diameter d_w of product grade A (M3 to M24) or B (M30, M36: ISO 4014
//    defines grade A only up to M24);
//  - hexagon nut style 1, ISO 4032: maximum height m and minimum bearing face diameter d_w (its
//    width across flats is the bolt's);
//  - clearance hole, ISO 273: d_h of the fine, medium and coarse series.
// Only the preferred sizes M3, M4, M5, M6, M8, M10, M12, M16, M20, M24, M30 and M36 are held.
struct MetricFastener {
  double nominal_diameter;
  double pitch;
  double width_across_flats;
  double head_height;
  double head_bearing_diameter;
  char head_product_grade;  // 'A' or 'B', the grade head_bearing_diameter is of
  double nut_height;
  double nut_bearing_diameter;
  double clearance_fine;
  double clearance_medium;
  double clearance_coarse;

  double clearance_hole(ClearanceSeries series) const;
};

// Every size held, smallest first.
std::span<const MetricFastener> MetricFasteners();

// The size of nominal diameter d (metres, matched to 1 nm); throws UserError naming the sizes held
// when there is none.
const MetricFastener& MetricFastenerOf(double nominal_diameter);

}  // namespace fitfeel::thread
