#include "framework/model/elastic_limit.h"

#include <cmath>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

void CheckYield(double yield_strength) {
  if (!std::isfinite(yield_strength) || !(yield_strength > 0.0)) {
    throw UserError("the elastic limit needs a positive yield strength");
  }
}

}  // namespace

double HubYieldPressure(double d, double outer_diameter, double yield_strength) {
  CheckYield(yield_strength);
  if (!(d > 0.0) || !(outer_diameter > d) || !std::isfinite(outer_diameter)) {
    throw UserError("the hub's elastic limit needs 0 < bore < outer diameter");
  }
  const double q = d / outer_diameter;
  return (1.0 - q * q) * yield_strength / std::sqrt(3.0);
}

double ShaftYieldPressure(double d, double bore, double yield_strength) {
  CheckYield(yield_strength);
  if (!(d > 0.0) || !(bore >= 0.0) || !(bore < d)) {
    throw UserError("the shaft's elastic limit needs 0 <= bore < diameter");
  }
  if (bore == 0.0) return yield_strength;
  const double q = bore / d;
  return (1.0 - q * q) * yield_strength / std::sqrt(3.0);
}

double HertzYieldPeakPressure(double yield_strength) {
  CheckYield(yield_strength);
  return 1.61 * yield_strength;
}

}  // namespace fitfeel
