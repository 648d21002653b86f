// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/planar/planar_surface.h"

FITFEEL_REGISTER_SURFACE(
    fitfeel::planar::PlanarSurface, "fitfeel.surface.planar", "1.0.0",
    "Parallel key in keyway, square shaft in square hole (flat faces sliding along y)");
