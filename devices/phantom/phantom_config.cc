// Scenario-facing part of the Phantom device.
#include "devices/phantom/phantom_device.h"
#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel::phantom {

void PhantomDevice::DoConfigure(const ConfigNode& node) {
  node.ExpectOnlyKeys({"plugin", "model", "spec", "auto_calibrate"});
  PhantomSettings settings;
  if (auto n = node.Find("model")) {
    settings.model = n->AsString();
    if (!FindDeviceSpec(settings.model)) n->Fail("a known device model", n->Describe());
  }
  if (auto n = node.Find("spec")) {
    const DeviceSpec base =
        settings.model.empty() ? DeviceSpec{} : LookupDeviceSpec(settings.model);
    settings.spec = ParseDeviceSpec(*n, base);
    if (settings.spec->model.empty()) settings.spec->model = "Phantom";
    try {
      ValidateDeviceSpec(*settings.spec);
    } catch (const UserError& e) {
      n->Fail("a complete device spec or a known model to start from", e.what());
    }
  }
  if (auto n = node.Find("auto_calibrate")) settings.auto_calibrate = n->AsBool();
  Configure(settings);
}

}  // namespace fitfeel::phantom
