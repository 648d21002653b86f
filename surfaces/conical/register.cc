// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/conical/conical_surface.h"

FITFEEL_REGISTER_SURFACE(fitfeel::conical::ConicalSurface, "fitfeel.surface.conical", "1.0.0",
                         "Taper pin in a taper-reamed hole (ISO 2339 1:50), DIN 7190 press fit");
