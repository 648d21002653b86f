// Deliberately broken test plugin: built by another compiler.
// Everything else is what plugin_entry.h builds, so the registry must refuse it for this alone.
#include "framework/plugin/plugin_entry.h"
#include "tests/plugins/common/test_objects.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::DeviceEntry<fitfeel::test_plugins::StillDevice>(
        "fitfeel.test.wrong_fingerprint", "1.0.0", "broken test plugin: built by another compiler"),
};

constexpr FitfeelPluginDescriptor Broken() {
  FitfeelPluginDescriptor d = fitfeel::plugin::MakeDescriptor(kEntries);
  d.build_fingerprint = "abi=1;cxx=4.2.1 Compatible Clang 15.0.0;glibcxx=9;eigen=3.3.7";
  return d;
}

constexpr FitfeelPluginDescriptor kDescriptor = Broken();

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
