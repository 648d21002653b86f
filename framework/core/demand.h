#pragma once

#include "framework/core/export.h"

namespace fitfeel::internal {

// Prints "file:line: demand failed: condition" to stderr and aborts. Never returns.
[[noreturn]] FITFEEL_API void DemandFailed(const char* condition, const char* file,
                                           int line) noexcept;

}  // namespace fitfeel::internal

// A contract check of a public wrapper that stays on in every build type (Release defines NDEBUG,
// which removes assert()): a violated demand is a programming error of the caller, so the process
// aborts with where and what, as DRAKE_DEMAND does. Cheap enough for the tick (one branch); plain
// assert() is left for checks inside a hot loop.
#define FITFEEL_DEMAND(condition)                                              \
  do {                                                                         \
    if (!(condition)) [[unlikely]] {                                           \
      ::fitfeel::internal::DemandFailed(#condition, __FILE__, __LINE__);       \
    }                                                                          \
  } while (false)
