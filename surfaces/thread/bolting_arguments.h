#pragma once

#include <string_view>

#include "framework/core/quantity.h"

namespace fitfeel::thread {

// Argument checks shared by the bolted-joint library (fastener tables, property classes, VDI 2230
// resiliences, tightening torque, load distribution). Each throws UserError reading
// "<function>: <argument> must be <condition>, found <value>", the value in a unit suited to its
// magnitude, so that a caller deep inside a contact model learns which input was wrong.

// value finite and > 0.
void RequirePositive(std::string_view function, std::string_view argument, double value,
                     Dimension dimension);
// value finite and >= 0.
void RequireNonNegative(std::string_view function, std::string_view argument, double value,
                        Dimension dimension);
// value finite and in [low, high].
void RequireWithin(std::string_view function, std::string_view argument, double value, double low,
                   double high, Dimension dimension);
// smaller < larger, both already checked finite; the message names both.
void RequireLess(std::string_view function, std::string_view smaller_name, double smaller,
                 std::string_view larger_name, double larger, Dimension dimension);

}  // namespace fitfeel::thread
