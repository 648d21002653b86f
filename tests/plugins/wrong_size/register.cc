// Deliberately broken test plugin: descriptor 8 bytes smaller than this framework's.
// Everything else is what plugin_entry.h builds, so the registry must refuse it for this alone.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::DeviceEntry<fitfeel::test_plugins::StillDevice>(
        "fitfeel.test.wrong_size", "1.0.0",
        "broken test plugin: descriptor 8 bytes smaller than this framework's"),
};

constexpr FitfeelPluginDescriptor Broken() {
  FitfeelPluginDescriptor d = fitfeel::plugin::MakeDescriptor(kEntries);
  d.descriptor_size -= 8;
  return d;
}

constexpr FitfeelPluginDescriptor kDescriptor = Broken();

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
