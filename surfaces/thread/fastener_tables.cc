#include "surfaces/thread/fastener_tables.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::thread {
namespace {

constexpr double kMm = 1e-3;

constexpr MetricFastener Size(double d, double p, double s, double k, double head_dw, char grade,
                              double m, double nut_dw, double fine, double medium, double coarse) {
  return {d * kMm, p * kMm,      s * kMm,    k * kMm,      head_dw * kMm, grade,
          m * kMm, nut_dw * kMm, fine * kMm, medium * kMm, coarse * kMm};
}

// Columns: d, P (ISO 261 coarse); s, k, d_w min (ISO 4014 / ISO 4017) and its product grade;
// m max, d_w min (ISO 4032 style 1); d_h fine, medium, coarse (ISO 273). Millimetres.
constexpr std::array kSizes = {
    Size(3, 0.5, 5.5, 2.0, 4.57, 'A', 2.4, 4.6, 3.2, 3.4, 3.6),
    Size(4, 0.7, 7, 2.8, 5.88, 'A', 3.2, 5.9, 4.3, 4.5, 4.8),
    Size(5, 0.8, 8, 3.5, 6.88, 'A', 4.7, 6.9, 5.3, 5.5, 5.8),
    Size(6, 1.0, 10, 4.0, 8.88, 'A', 5.2, 8.9, 6.4, 6.6, 7.0),
    Size(8, 1.25, 13, 5.3, 11.63, 'A', 6.8, 11.6, 8.4, 9, 10),
    Size(10, 1.5, 16, 6.4, 14.63, 'A', 8.4, 14.6, 10.5, 11, 12),
    Size(12, 1.75, 18, 7.5, 16.63, 'A', 10.8, 16.6, 13, 13.5, 14.5),
    Size(16, 2.0, 24, 10, 22.49, 'A', 14.8, 22.5, 17, 17.5, 18.5),
    Size(20, 2.5, 30, 12.5, 28.19, 'A', 18, 27.7, 21, 22, 24),
    Size(24, 3.0, 36, 15, 33.61, 'A', 21.5, 33.3, 25, 26, 28),
    Size(30, 3.5, 46, 18.7, 42.75, 'B', 25.6, 42.8, 31, 33, 35),
    Size(36, 4.0, 55, 22.5, 51.11, 'B', 31, 51.1, 37, 39, 42),
};

}  // namespace

double MetricFastener::clearance_hole(ClearanceSeries series) const {
  switch (series) {
    case ClearanceSeries::kFine:
      return clearance_fine;
    case ClearanceSeries::kMedium:
      return clearance_medium;
    case ClearanceSeries::kCoarse:
      return clearance_coarse;
  }
  return clearance_medium;
}

std::span<const MetricFastener> MetricFasteners() { return kSizes; }

const MetricFastener& MetricFastenerOf(double nominal_diameter) {
  for (const MetricFastener& size : kSizes) {
    if (std::abs(size.nominal_diameter - nominal_diameter) < 1e-9) return size;
  }
  std::string held;
  for (const MetricFastener& size : kSizes) {
    char name[16];
    std::snprintf(name, sizeof name, "M%g", size.nominal_diameter / kMm);
    held += held.empty() ? name : std::string(", ") + name;
  }
  throw UserError("MetricFastenerOf: no ISO metric coarse-pitch fastener of nominal diameter " +
                  FormatQuantity(nominal_diameter, Dimension::kLength) + "; the tables hold " +
                  held);
}

}  // namespace fitfeel::thread
