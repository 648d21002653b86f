// libFuzzer target: the recording reader (devices/replay reads what `run.outputs: recording`
// wrote). Any file either reads into samples that are finite, within physical bounds and
// strictly increasing in time, or is refused with RecordingError naming its line; anything else
// (a crash, another exception, a sanitizer report, a sample that breaks those promises) is a
// finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "framework/device/physical_bounds.h"
#include "framework/device/recording.h"
#include "framework/testing/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file =
      fitfeel::test_support::WriteFuzzInput("recording.csv", data, size);
  try {
    const fitfeel::Recording recording = fitfeel::ReadRecording(file);
    double last = -std::numeric_limits<double>::infinity();
    for (const fitfeel::RecordedSample& s : recording.samples) {
      fitfeel::DeviceState state;
      state.position = s.position;
      state.orientation = s.orientation;
      state.velocity = s.velocity;
      state.angular_velocity = s.angular_velocity;
      if (!fitfeel::DeviceStateInBounds(state) || !std::isfinite(s.time) || !(s.time > last) ||
          !s.commanded.AllFinite() || !s.delivered.AllFinite()) {
        std::abort();
      }
      last = s.time;
    }
  } catch (const fitfeel::RecordingError& e) {
    if (e.line() < 0) std::abort();
  }
  return 0;
}
