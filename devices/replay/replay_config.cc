// Scenario-facing part of the replay device.
#include <cstdio>
#include <limits>
#include <optional>
#include <utility>

#include "devices/replay/replay_device.h"
#include "framework/core/path_check.h"
#include "framework/device/device_specs.h"

namespace fitfeel::replay {

void ReplayDevice::DoConfigure(const ConfigNode& node) {
  node.ExpectOnlyKeys({"plugin", "file", "speed", "start", "loop", "model", "spec"});
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ReplaySettings settings;
  const ConfigNode file = node.Child("file");
  settings.file = file.AsString();
  if (settings.file.is_relative()) {
    settings.file = std::filesystem::path(node.file()).parent_path() / settings.file;
  }
  if (const std::string why = WhyNotReadableFile(settings.file); !why.empty()) {
    // Appended rather than concatenated: GCC 12 at -O3 reports a false -Warray-bounds inside
    // operator+ of a one-character literal and a string here (GCC bug 105651).
    std::string found = "'";
    found += settings.file.string();
    found += "', which ";
    found += why;
    file.Fail("a readable recording file", found);
  }
  if (auto n = node.Find("speed")) {
    settings.speed = n->AsQuantityIn(Dimension::kDimensionless, 0.0, kInf, false);
  }
  const std::optional<ConfigNode> start = node.Find("start");
  if (start) settings.start = start->AsQuantityIn(Dimension::kTime, 0.0, kInf);
  if (auto n = node.Find("loop")) settings.loop = n->AsBool();
  if (auto n = node.Find("model")) {
    settings.model = n->AsString();
    if (!FindDeviceSpec(settings.model)) n->Fail("a known device model", n->Describe());
  }
  if (auto n = node.Find("spec")) {
    // Overrides apply on top of the model's spec: the key's, else the recording's.
    DeviceSpec base;
    if (!settings.model.empty()) {
      base = LookupDeviceSpec(settings.model);
    } else if (auto known = FindDeviceSpec(ReadRecording(settings.file).info.device_model)) {
      base = *known;
    }
    settings.spec = ParseDeviceSpec(*n, base);
    if (settings.spec->model.empty()) settings.spec->model = "replay";
    try {
      ValidateDeviceSpec(*settings.spec);
    } catch (const UserError& e) {
      n->Fail(
          "a complete device spec (max_force, max_continuous_force, max_stiffness, damping, "
          "workspace) or a known model to start from",
          e.what());
    }
  }
  // The recording's own errors carry its file and line; the start is checked against its length
  // here so that the refusal names the key.
  Recording recording = ReadRecording(settings.file);
  if (recording.samples.empty()) file.Fail("a recording with samples", "none");
  const double duration = recording.samples.back().time - recording.samples.front().time;
  if (start && settings.start > duration) {
    char text[96];
    std::snprintf(text, sizeof text, "a start within the recording's %g s", duration);
    start->Fail(text, start->Describe());
  }
  Configure(settings, std::move(recording));
}

}  // namespace fitfeel::replay
