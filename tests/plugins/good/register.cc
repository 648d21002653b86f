// The good test plugin: one surface type and one device, loaded by the registry tests and usable
// by any test that needs objects from a real plugin library.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::SurfaceEntry<fitfeel::test_plugins::InertSurface>(
        "fitfeel.test.inert_surface", "1.0.0", "Test surface type that models nothing"),
    fitfeel::plugin::DeviceEntry<fitfeel::test_plugins::StillDevice>(
        "fitfeel.test.still_device", "1.0.0", "Test device resting at the origin"),
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
