// The plugin's only exported symbol.
#include "devices/simulated/simulated_device.h"
#include "framework/plugin/plugin_entry.h"

FITFEEL_REGISTER_DEVICE(
    fitfeel::simulated::SimulatedDevice, "fitfeel.device.simulated", "1.0.0",
    "simulated robot (constant speed, radial load) or scripted hand with spring-damper");
