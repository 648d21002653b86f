#include "framework/conformance/surface_conformance.h"

// The suite's macro names the test suite unqualified.
using namespace fitfeel::conformance;  // NOLINT(build/namespaces)
FITFEEL_SURFACE_CONFORMANCE(Thread, "surfaces/thread/test/conformance.yaml");
