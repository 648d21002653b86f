#pragma once

// The simulated hand in place of a scenario's device (docs/lead-in.md), for tests and benchmarks
// that insert parts as a person does: 0.5 kg held by 2000 N/m and 20 N*s/m to a target that moves
// through `waypoints` (YAML flow lines under `waypoints:`), physiological tremor (0.1 mm at
// 10 Hz), aimed `aim` metres off the axis along x; the run lasts `seconds`.

#include <sstream>
#include <stdexcept>
#include <string>

namespace fitfeel::test_support {

inline constexpr double kHandStiffness = 2000.0;  // N/m
inline constexpr double kHandTremor = 0.1e-3;     // m

// Pushing in: 27 mm along the axis in 3 s from 2 mm in front of the entrance.
inline constexpr const char* kHandPushIn =
    "    - {time: 0 s, position: [0 mm, -2 mm, 0 mm]}\n"
    "    - {time: 3 s, position: [0 mm, 25 mm, 0 mm]}\n";

// `scenario_text` (a scenario file's text) with its device section replaced by the hand, and its
// `part_motion` section (a robot's load on the part) dropped: the hand holds the part.
// Throws std::invalid_argument if the text has no `device:` followed by a `run:` section.
inline std::string WithHand(const std::string& scenario_text, double aim,
                            const std::string& waypoints, double seconds) {
  const std::size_t device = scenario_text.find("\ndevice:");
  const std::size_t run = scenario_text.find("\nrun:");
  if (device == std::string::npos || run == std::string::npos || run < device) {
    throw std::invalid_argument("hand scene: no device section followed by a run section");
  }
  std::ostringstream hand;
  hand << "\ndevice:\n  plugin: fitfeel.device.simulated\n  mode: scripted\n"
       << "  hand: {mass: 0.5 kg, stiffness: " << kHandStiffness
       << " N/m, damping: 20 N*s/m, tremor: true, aim_error: [" << aim * 1e3 << " mm, 0 mm]}\n"
       << "  waypoints:\n"
       << waypoints;
  std::string text = scenario_text.substr(0, device) + hand.str() + scenario_text.substr(run);
  if (const std::size_t motion = text.find("\npart_motion:"); motion != std::string::npos) {
    // To the next line that starts a section (not indented, not a comment).
    std::size_t end = text.find('\n', motion + 1);
    while (end != std::string::npos && end + 1 < text.size() &&
           (text[end + 1] == ' ' || text[end + 1] == '#')) {
      end = text.find('\n', end + 1);
    }
    text.erase(motion, (end == std::string::npos ? text.size() : end) - motion);
  }
  // Every `duration:` to the end of its line (by hand: GCC 12 warns inside <regex> under the
  // sanitizers, and warnings are errors).
  const std::string key = "duration: ", value = std::to_string(seconds) + " s";
  for (std::size_t at = text.find(key); at != std::string::npos;
       at = text.find(key, at + key.size() + value.size())) {
    const std::size_t end = text.find('\n', at);
    text.replace(at + key.size(), (end == std::string::npos ? text.size() : end) - at - key.size(),
                 value);
  }
  return text;
}

// `scenario_text` with its `moving:` line naming `part` instead. Throws std::invalid_argument if
// the text has no top-level `moving:` line.
inline std::string WithMoving(const std::string& scenario_text, const std::string& part) {
  const std::string key = "\nmoving: ";
  const std::size_t at = scenario_text.find(key);
  if (at == std::string::npos) throw std::invalid_argument("hand scene: no moving line");
  const std::size_t end = scenario_text.find('\n', at + key.size());
  return scenario_text.substr(0, at + key.size()) + part +
         (end == std::string::npos ? std::string() : scenario_text.substr(end));
}

}  // namespace fitfeel::test_support
