#pragma once

// Constants the tests write quantities with. One definition for all: a unity build compiles
// several test files as one translation unit, where file-local copies would collide.
#include <limits>
#include <numbers>

namespace fitfeel::test_support {

inline constexpr double kUm = 1e-6;
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace fitfeel::test_support
