// Deliberately broken test plugin: it exports a misspelled hook, so the registration hook the
// registry looks for (fitfeel_plugin_register) is absent.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::DeviceEntry<fitfeel::test_plugins::StillDevice>("fitfeel.test.no_hook",
                                                                     "1.0.0", "broken test plugin"),
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_register_plugin() {
  return &kDescriptor;
}
