#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framework/core/error.h"
#include "framework/core/export.h"
#include "framework/core/wrench.h"

namespace fitfeel {

// One tick of the device stream, SI, scene frame. A plain struct the runtime fills into a buffer
// it allocated before the run; nothing here does I/O in the tick.
struct RecordedSample {
  double time = 0.0;  // s since the start of the run
  Eigen::Vector3d position{0.0, 0.0, 0.0};
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity{0.0, 0.0, 0.0};
  Eigen::Vector3d angular_velocity{0.0, 0.0, 0.0};
  std::uint32_t buttons = 0;
  Wrench commanded;  // what the framework wrote to the device (after the safety chain)
  Wrench delivered;  // what the device reported delivering (DeviceState::delivered)
  Eigen::Vector2d load{0.0, 0.0};  // the radial load that acted on the part (x, z), N
};

// Header facts of a recording.
struct RecordingInfo {
  std::string device_model;  // the device's spec model, empty when unknown
};

struct Recording {
  RecordingInfo info;
  std::vector<RecordedSample> samples;
};

// A recording file that is malformed, truncated or without units. what() reads
// "<file>:<line>: <reason>".
class FITFEEL_API RecordingError : public UserError {
 public:
  RecordingError(std::filesystem::path file, int line, std::string reason);
  ~RecordingError() override;
  const std::filesystem::path& file() const { return file_; }
  int line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  std::filesystem::path file_;
  int line_ = 0;
  std::string reason_;
};

// File format, version 2 (text, one sample per line, whitespace-separated):
//   # fitfeel-recording 2
//   # device: PHANTOM Desktop          (optional metadata lines "# key: value")
//   t_s x_m y_m z_m qw_1 qx_1 qy_1 qz_1 vx_m/s ... buttons_bits fx_cmd_N ... tz_dlv_N*m settle_x_N settle_z_N
//   <29 numbers per line>
//   # end: <sample count> samples
// Every column name ends in its unit after the last '_'. Numbers are written in the shortest form
// that reads back to the same double, so a recording round-trips bit for bit. The end line makes a
// truncated file detectable.
// Version 2 added the radial load that acted on the part (settle_x_N, settle_z_N: the scene's
// part_motion.radial_load once inside); a replay takes the load from its own scene, the columns
// record it. Version 1 files are refused with the version named.
inline constexpr int kRecordingFormatVersion = 2;
FITFEEL_API const std::vector<std::string>& RecordingColumns();

// Writes a recording sample by sample as a run produces them (from a thread outside the tick),
// holding at most about 1 MiB in memory: the file at `file` is created at construction and
// complete only after Finish. Append checks each sample (finite values, strictly increasing time)
// and throws UserError for a bad one; the caller removes the incomplete file.
class FITFEEL_API RecordingWriter {
 public:
  // Throws UserError when the file cannot be created or the info cannot be written.
  RecordingWriter(std::filesystem::path file, const RecordingInfo& info);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  void Append(const RecordedSample& sample);
  // Writes the end line and closes the file; throws UserError on a write failure.
  void Finish();
  std::uint64_t count() const { return count_; }

 private:
  void Flush();

  std::filesystem::path file_;
  std::ofstream out_;
  std::string line_;
  std::uint64_t count_ = 0;
  double last_time_ = 0.0;
};

// Writes after the run. Checks every sample first (finite values, strictly increasing time) and
// writes to a temporary file renamed into place, so a failure never leaves a half-written file.
// Throws UserError (bad sample, unwritable path).
FITFEEL_API void WriteRecording(const std::filesystem::path& file, const RecordingInfo& info,
                                std::span<const RecordedSample> samples);

// Reads and checks a recording; throws RecordingError with the line and reason for a missing or
// unknown format line, a column without or with the wrong unit, a wrong field count, a field that
// is not a finite number or lies outside physical sense (positions beyond 10 m, speeds above
// 100 m/s, forces above 10 MN: recording.cc), time not strictly increasing, a non-unit quaternion, or a missing or
// inconsistent end line (truncation).
FITFEEL_API Recording ReadRecording(const std::filesystem::path& file);

}  // namespace fitfeel
