#include "framework/conformance/surface_conformance.h"

FITFEEL_SURFACE_CONFORMANCE(Thread, "surfaces/thread/test/conformance.yaml");
