#pragma once

// Internal to the framework library: the structured form of ParseQuantity's diagnosis, so that
// ConfigNode can report "expected <dimension>, found <what was wrong>" without re-parsing a
// message.

#include <string>
#include <string_view>

#include "framework/core/quantity.h"

namespace fitfeel::internal {

struct QuantityParse {
  double value = 0.0;
  // Empty on success; otherwise what was found, e.g. "'20 kg' (kg is a unit of mass)".
  std::string problem;
};

QuantityParse TryParseQuantity(std::string_view text, Dimension dimension);

// "a length", "a dimensionless number", ... (no unit list).
std::string DimensionName(Dimension dimension);

}  // namespace fitfeel::internal
