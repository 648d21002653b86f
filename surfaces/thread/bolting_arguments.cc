#include "surfaces/thread/bolting_arguments.h"

#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace fitfeel::thread {
namespace {

[[noreturn]] void FailArgument(std::string_view function, std::string_view argument,
                               std::string_view condition, double value, Dimension dimension) {
  throw UserError(std::string(function) + ": " + std::string(argument) + " must be " +
                  std::string(condition) + ", found " + FormatQuantity(value, dimension));
}

}  // namespace

void RequirePositive(std::string_view function, std::string_view argument, double value,
                     Dimension dimension) {
  if (!std::isfinite(value) || value <= 0.0) {
    FailArgument(function, argument, "finite and positive", value, dimension);
  }
}

void RequireNonNegative(std::string_view function, std::string_view argument, double value,
                        Dimension dimension) {
  if (!std::isfinite(value) || value < 0.0) {
    FailArgument(function, argument, "finite and not negative", value, dimension);
  }
}

void RequireWithin(std::string_view function, std::string_view argument, double value, double low,
                   double high, Dimension dimension) {
  if (!std::isfinite(value) || value < low || value > high) {
    FailArgument(
        function, argument,
        "in [" + FormatQuantity(low, dimension) + ", " + FormatQuantity(high, dimension) + "]",
        value, dimension);
  }
}

void RequireLess(std::string_view function, std::string_view smaller_name, double smaller,
                 std::string_view larger_name, double larger, Dimension dimension) {
  if (!(smaller < larger)) {
    throw UserError(std::string(function) + ": " + std::string(smaller_name) + " (" +
                    FormatQuantity(smaller, dimension) + ") must be less than " +
                    std::string(larger_name) + " (" + FormatQuantity(larger, dimension) + ")");
  }
}

}  // namespace fitfeel::thread
