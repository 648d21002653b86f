// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/thread/thread_surface.h"

FITFEEL_REGISTER_SURFACE(
    fitfeel::thread::ThreadSurface, "fitfeel.surface.thread", "1.0.0",
    "Threaded (helicoid) mating: screw motion, flank friction and tightening (VDI 2230)");
