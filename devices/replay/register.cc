#include "devices/replay/replay_device.h"
#include "framework/plugin/abi.h"
#include "framework/plugin/fingerprint.h"

namespace {

void* MakeReplayDevice() { return static_cast<fitfeel::Device*>(new fitfeel::ReplayDevice()); }

const FitfeelPluginEntry kEntries[] = {
    {"fitfeel.device.replay", kFitfeelDevicePlugin, "1.0.0",
     "plays a recorded device stream back as a device (seek, speed, loop)", &MakeReplayDevice},
};

const FitfeelPluginDescriptor kDescriptor = {
    FITFEEL_PLUGIN_ABI_VERSION,
    sizeof(FitfeelPluginDescriptor),
    alignof(FitfeelPluginDescriptor),
    sizeof(FitfeelPluginEntry),
    FITFEEL_BUILD_FINGERPRINT,
    sizeof(kEntries) / sizeof(kEntries[0]),
    kEntries,
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
