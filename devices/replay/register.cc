// The plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "devices/replay/replay_device.h"

FITFEEL_REGISTER_DEVICE(fitfeel::replay::ReplayDevice, "fitfeel.device.replay", "1.0.0",
                        "plays a recorded device stream back as a device (seek, speed, loop)");
