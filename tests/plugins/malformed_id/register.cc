// Deliberately broken test plugin: an id that is not dotted lowercase.
// Everything else is what plugin_entry.h builds, so the registry must refuse it for this alone.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    FitfeelPluginEntry{"Fitfeel.Test.Bad-Id", kFitfeelDevicePlugin, "1.0.0", "broken test plugin",
                       FITFEEL_DEVICE_FACTORY(fitfeel::test_plugins::StillDevice)},
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
