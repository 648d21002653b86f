#include "devices/replay/replay_device.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel::replay {

void ReplayDevice::Configure(const ReplaySettings& settings) {
  Configure(settings, ReadRecording(settings.file));
}

void ReplayDevice::Configure(const ReplaySettings& settings, Recording recording) {
  if (!(settings.speed > 0.0) || !std::isfinite(settings.speed)) {
    throw UserError("replay: speed must be a positive factor");
  }
  if (!(settings.start >= 0.0) || !std::isfinite(settings.start)) {
    throw UserError("replay: start must be a time of zero or more seconds");
  }
  if (recording.samples.empty()) {
    throw UserError("replay: recording " + settings.file.string() + " holds no samples");
  }
  const double duration = recording.samples.back().time - recording.samples.front().time;
  if (settings.start > duration) {
    throw UserError("replay: start " + std::to_string(settings.start) +
                    " s is past the end of the recording (" + std::to_string(duration) + " s)");
  }
  DeviceSpec spec;
  if (settings.spec) {
    spec = *settings.spec;
  } else {
    const std::string model =
        !settings.model.empty() ? settings.model : recording.info.device_model;
    if (model.empty()) {
      throw UserError("replay: recording " + settings.file.string() +
                      " names no device model; give `model` or `spec` in the device section");
    }
    spec = LookupDeviceSpec(model);
  }
  ValidateDeviceSpec(spec);
  settings_ = settings;
  recording_ = std::move(recording);
  spec_ = spec;
  configured_ = true;
  active_ = true;
  written_.SetZero();
}

void ReplayDevice::DoStart(double) {
  if (!configured_) throw UserError("replay: device started before it was configured");
  active_ = true;
  written_.SetZero();
}

void ReplayDevice::DoRead(double time, DeviceState* out) noexcept {
  const std::vector<RecordedSample>& s = recording_.samples;
  out->time = time;
  out->delivered = written_;
  if (s.empty()) return;  // unconfigured: Start refuses, this only guards misuse
  const double t0 = s.front().time;
  const double t_end = s.back().time;
  const double duration = t_end - t0;
  const double run_time = std::isfinite(time) ? std::max(0.0, time) : 0.0;
  double offset = settings_.start + settings_.speed * run_time;
  if (settings_.loop && duration > 0.0) {
    offset = std::fmod(offset, duration);
  } else if (offset >= duration) {
    offset = duration;
    active_ = false;
  }
  const double tau = t0 + offset;
  // Last sample at or before tau.
  const auto after = std::upper_bound(s.begin(), s.end(), tau,
                                      [](double t, const RecordedSample& x) { return t < x.time; });
  const std::size_t i = after == s.begin() ? 0 : static_cast<std::size_t>(after - s.begin()) - 1;
  const RecordedSample& a = s[i];
  out->buttons = a.buttons;
  if (i + 1 >= s.size() || tau == a.time) {
    out->position = a.position;
    out->orientation = a.orientation;
    out->velocity = a.velocity;
    out->angular_velocity = a.angular_velocity;
    return;
  }
  const RecordedSample& b = s[i + 1];
  const double u = (tau - a.time) / (b.time - a.time);
  out->position = a.position + u * (b.position - a.position);
  out->orientation = a.orientation.slerp(u, b.orientation);
  out->velocity = a.velocity + u * (b.velocity - a.velocity);
  out->angular_velocity = a.angular_velocity + u * (b.angular_velocity - a.angular_velocity);
}

void ReplayDevice::DoWrite(const Wrench& wrench) noexcept { written_ = wrench; }

}  // namespace fitfeel::replay
