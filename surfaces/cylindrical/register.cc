// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/cylindrical/cylindrical_surface.h"

FITFEEL_REGISTER_SURFACE(
    fitfeel::cylindrical::CylindricalSurface, "fitfeel.surface.cylindrical", "1.0.0",
    "Cylindrical mating (shaft in bushing, pin in hole): the paper's GPS skin model shapes");
