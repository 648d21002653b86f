// Deliberately broken test plugin: an entry without a factory.
// Everything else is what plugin_entry.h builds, so the registry must refuse it for this alone.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    FitfeelPluginEntry{"fitfeel.test.null_factory", kFitfeelDevicePlugin, "1.0.0",
                       "broken test plugin", nullptr},
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
