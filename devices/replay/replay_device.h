#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "framework/device/device.h"
#include "framework/device/recording.h"

namespace fitfeel::replay {

struct ReplaySettings {
  std::filesystem::path file;
  double speed = 1.0;  // recording seconds per run second
  double start = 0.0;  // s into the recording at which the run starts (seek)
  bool loop = false;   // wrap around at the end instead of ending
  // Spec of the replayed device: `spec` if given, else the table entry for `model`, else the one
  // for the recording's "# device:" line.
  std::string model;
  std::optional<DeviceSpec> spec;
};

// Plays a recording back as a device: the hand's pose, velocity and buttons at run time t are the
// recording's at t_0 + start + speed * t, linearly interpolated between samples (orientation by
// slerp, buttons held from the earlier sample). Deterministic: the same reads give the same states,
// and a read at a recorded sample's time returns that sample exactly. Written wrenches are not
// rendered; the device reports them back as delivered on the next read (an ideal device).
class ReplayDevice final : public Device {
 public:
  // Loads and checks the recording (RecordingError, UserError).
  void Configure(const ReplaySettings& settings);
  // The same with the recording already read from settings.file.
  void Configure(const ReplaySettings& settings, Recording recording);
  using Device::Configure;

  DeviceSpec DoSpec() const override { return spec_; }
  bool DoActive() const override { return active_; }
  const Recording& recording() const { return recording_; }

 protected:
  void DoConfigure(const ConfigNode& node) override;
  void DoStart(double period) override;
  void DoRead(double time, DeviceState* out) noexcept override;
  void DoWrite(const Wrench& wrench) noexcept override;

 private:
  ReplaySettings settings_;
  Recording recording_;
  DeviceSpec spec_;
  bool configured_ = false;
  bool active_ = true;
  Wrench written_;
};

}  // namespace fitfeel::replay
