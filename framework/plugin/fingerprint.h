#pragma once

#include <Eigen/Core>

#include "framework/plugin/abi.h"  // FITFEEL_PLUGIN_ABI_VERSION, expanded below

// Identifies the build settings that must match between the framework and a plugin for C++
// objects to cross the library boundary: compiler, C++ standard library, Eigen and the ABI, and
// how Eigen allocates (from malloc directly, or through its own aligned wrapper, which it uses
// under AddressSanitizer: a vector allocated one way and freed the other corrupts the heap).
#define FITFEEL_STR2(x) #x
#define FITFEEL_STR(x) FITFEEL_STR2(x)
#define FITFEEL_BUILD_FINGERPRINT \
  "abi=" FITFEEL_STR(FITFEEL_PLUGIN_ABI_VERSION) ";cxx=" __VERSION__                      \
  ";glibcxx=" FITFEEL_STR(_GLIBCXX_RELEASE) ";eigen=" FITFEEL_STR(EIGEN_WORLD_VERSION) "." \
  FITFEEL_STR(EIGEN_MAJOR_VERSION) "." FITFEEL_STR(EIGEN_MINOR_VERSION)                    \
  ";eigen_malloc_aligned=" FITFEEL_STR(EIGEN_MALLOC_ALREADY_ALIGNED)
