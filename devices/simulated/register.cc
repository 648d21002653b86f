// The plugin's only exported symbol.
#include "devices/simulated/simulated_device.h"
#include "framework/plugin/abi.h"
#include "framework/plugin/fingerprint.h"

namespace {

void* MakeSimulatedDevice() {
  try {
    return static_cast<fitfeel::Device*>(new fitfeel::simulated::SimulatedDevice());
  } catch (...) {
    return nullptr;
  }
}

const FitfeelPluginEntry kEntries[] = {
    {"fitfeel.device.simulated", kFitfeelDevicePlugin, "1.0.0",
     "simulated robot (constant speed, radial load) or scripted hand with spring-damper",
     &MakeSimulatedDevice},
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
