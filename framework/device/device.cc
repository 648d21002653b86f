#include "framework/device/device.h"

#include <cmath>

#include "framework/core/demand.h"
#include "framework/core/error.h"

namespace fitfeel {

Device::~Device() = default;

void Device::Configure(const ConfigNode& node) { DoConfigure(node); }

void Device::Start(double period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw UserError("device tick period must be a positive number of seconds");
  }
  DoStart(period);
}

void Device::Stop() noexcept { DoStop(); }

void Device::Read(double time, DeviceState* out) noexcept {
  FITFEEL_DEMAND(out != nullptr);
  DoRead(time, out);
}

void Device::Write(const Wrench& wrench) noexcept {
  // The safety chain guarantees finite wrenches; a device must never see anything else.
  if (!wrench.AllFinite()) {
    DoWrite(Wrench{});
    return;
  }
  DoWrite(wrench);
}

void Device::RunServoLoop(double duration, const std::function<bool(double)>& tick) {
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw UserError("device servo loop: the duration must be a positive number of seconds");
  }
  if (!tick) throw UserError("device servo loop: no tick to call");
  DoRunServoLoop(duration, tick);
}

void Device::DoRunServoLoop(double, const std::function<bool(double)>&) {
  throw UnsupportedError("this device does not own a servo clock; run it from the scheduler");
}

}  // namespace fitfeel
