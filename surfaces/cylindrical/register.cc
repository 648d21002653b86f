// The plugin's only exported symbol (hand-written descriptor, per the plugin ABI in
// framework/plugin/abi.h).
#include "framework/plugin/abi.h"
#include "framework/plugin/fingerprint.h"
#include "surfaces/cylindrical/cylindrical_surface.h"

namespace {

void* MakeCylindricalSurface() {
  // Converted to the base before void*, as the loader casts back to SurfaceType*.
  fitfeel::SurfaceType* surface = new fitfeel::cylindrical::CylindricalSurface();
  return static_cast<void*>(surface);
}

const FitfeelPluginEntry kEntries[] = {
    {"fitfeel.surface.cylindrical", kFitfeelSurfacePlugin, "1.0.0",
     "Cylindrical mating (shaft in bushing, pin in hole): the paper's GPS skin model shapes",
     &MakeCylindricalSurface},
};

const FitfeelPluginDescriptor kDescriptor = {
    FITFEEL_PLUGIN_ABI_VERSION,
    static_cast<std::uint32_t>(sizeof(FitfeelPluginDescriptor)),
    static_cast<std::uint32_t>(alignof(FitfeelPluginDescriptor)),
    static_cast<std::uint32_t>(sizeof(FitfeelPluginEntry)),
    FITFEEL_BUILD_FINGERPRINT,
    static_cast<std::uint32_t>(sizeof(kEntries) / sizeof(kEntries[0])),
    kEntries,
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
