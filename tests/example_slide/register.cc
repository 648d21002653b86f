// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "tests/example_slide/example_slide_surface.h"

FITFEEL_REGISTER_SURFACE(fitfeel::example_slide::SlideSurface, "fitfeel.surface.example_slide",
                         "1.0.0", "Guide example: a block sliding in a slot between two rails (size only)");
