// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "devices/phantom/phantom_device.h"

FITFEEL_REGISTER_DEVICE(
    fitfeel::phantom::PhantomDevice, "fitfeel.device.phantom", "1.0.0",
    "PHANTOM / Touch haptic device through the OpenHaptics HD API (libHD.so, loaded at run time)");
