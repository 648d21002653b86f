// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/spherical/spherical_surface.h"

FITFEEL_REGISTER_SURFACE(
    fitfeel::spherical::SphericalSurface, "fitfeel.surface.spherical", "1.0.0",
    "Ball in socket: spherical plain (knuckle) bearing, ISO 12240-1; friction torque");
