// Test plugin A of a pair that both claim the id fitfeel.test.duplicate (told apart by
// version 1.0.0): the registry keeps the first on the search path.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::DeviceEntry<fitfeel::test_plugins::StillDevice>(
        "fitfeel.test.duplicate", "1.0.0", "Duplicate test plugin A"),
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
