#include "framework/conformance/surface_conformance.h"

FITFEEL_SURFACE_CONFORMANCE(Planar, "surfaces/planar/test/conformance.yaml");
