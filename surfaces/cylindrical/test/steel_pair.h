#pragma once

#include "surfaces/cylindrical/elastic/harmonic_compliance.h"

namespace fitfeel::cylindrical::testing {

// A steel shaft of 20 mm in a steel hub of 30 mm outer diameter (E = 210 GPa, nu = 0.3).
inline PressFitSection SteelPair() {
  PressFitSection s;
  s.d1 = 0.020;
  s.d2 = 0.030;
  s.shaft = {"steel", 210e9, 0.3};
  s.hub = s.shaft;
  return s;
}

}  // namespace fitfeel::cylindrical::testing
