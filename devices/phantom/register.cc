#include "devices/phantom/phantom_device.h"
#include "framework/plugin/abi.h"
#include "framework/plugin/fingerprint.h"

namespace {

void* MakePhantomDevice() { return static_cast<fitfeel::Device*>(new fitfeel::PhantomDevice()); }

const FitfeelPluginEntry kEntries[] = {
    {"fitfeel.device.phantom", kFitfeelDevicePlugin, "1.0.0",
     "PHANTOM / Touch haptic device through the OpenHaptics HD API (libHD.so, loaded at run time)",
     &MakePhantomDevice},
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
