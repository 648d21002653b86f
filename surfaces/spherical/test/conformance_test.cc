#include "framework/conformance/surface_conformance.h"

// The suite's macro instantiates at global scope names declared in fitfeel::conformance.
using namespace fitfeel::conformance;  // NOLINT(google-build-using-namespace)

FITFEEL_SURFACE_CONFORMANCE(Spherical, "surfaces/spherical/test/conformance.yaml");
