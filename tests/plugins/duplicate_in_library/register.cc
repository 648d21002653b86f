// Deliberately broken test plugin: two entries with the same id.
// Everything else is what plugin_entry.h builds, so the registry must refuse it for this alone.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    FitfeelPluginEntry{"fitfeel.test.twice", kFitfeelDevicePlugin, "1.0.0", "broken test plugin",
                       FITFEEL_DEVICE_FACTORY(fitfeel::test_plugins::StillDevice)},
    FitfeelPluginEntry{"fitfeel.test.twice", kFitfeelSurfacePlugin, "1.0.0", "broken test plugin",
                       FITFEEL_SURFACE_FACTORY(fitfeel::test_plugins::InertSurface)},
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
