#include "framework/device/recording.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include "framework/core/line_endings.h"
#include "framework/core/os_reason.h"
#include "framework/device/physical_bounds.h"

namespace fitfeel {
namespace {

constexpr int kColumnCount = 29;
constexpr const char* kFormatLine = "# fitfeel-recording";
constexpr const char* kEndPrefix = "# end: ";

struct ColumnName {
  const char* name;
  const char* unit;
};

constexpr ColumnName kColumns[kColumnCount] = {
    {"t", "s"},        {"x", "m"},        {"y", "m"},      {"z", "m"},        {"qw", "1"},
    {"qx", "1"},       {"qy", "1"},       {"qz", "1"},     {"vx", "m/s"},     {"vy", "m/s"},
    {"vz", "m/s"},     {"wx", "rad/s"},   {"wy", "rad/s"}, {"wz", "rad/s"},   {"buttons", "bits"},
    {"fx_cmd", "N"},   {"fy_cmd", "N"},   {"fz_cmd", "N"}, {"tx_cmd", "N*m"}, {"ty_cmd", "N*m"},
    {"tz_cmd", "N*m"}, {"fx_dlv", "N"},   {"fy_dlv", "N"}, {"fz_dlv", "N"},   {"tx_dlv", "N*m"},
    {"ty_dlv", "N*m"}, {"tz_dlv", "N*m"}, {"settle_x", "N"}, {"settle_z", "N"},
};
constexpr int kButtonsColumn = 14;

// The 28 floating-point fields of a sample in column order (buttons excluded).
void Flatten(const RecordedSample& s, double* out) {
  int i = 0;
  out[i++] = s.time;
  for (int k = 0; k < 3; ++k) out[i++] = s.position[k];
  out[i++] = s.orientation.w();
  out[i++] = s.orientation.x();
  out[i++] = s.orientation.y();
  out[i++] = s.orientation.z();
  for (int k = 0; k < 3; ++k) out[i++] = s.velocity[k];
  for (int k = 0; k < 3; ++k) out[i++] = s.angular_velocity[k];
  for (int k = 0; k < 3; ++k) out[i++] = s.commanded.force[k];
  for (int k = 0; k < 3; ++k) out[i++] = s.commanded.torque[k];
  for (int k = 0; k < 3; ++k) out[i++] = s.delivered.force[k];
  for (int k = 0; k < 3; ++k) out[i++] = s.delivered.torque[k];
  for (int k = 0; k < 2; ++k) out[i++] = s.load[k];
}

void Unflatten(const double* in, RecordedSample* s) {
  int i = 0;
  s->time = in[i++];
  for (int k = 0; k < 3; ++k) s->position[k] = in[i++];
  const double w = in[i++], x = in[i++], y = in[i++], z = in[i++];
  s->orientation = Eigen::Quaterniond(w, x, y, z);
  for (int k = 0; k < 3; ++k) s->velocity[k] = in[i++];
  for (int k = 0; k < 3; ++k) s->angular_velocity[k] = in[i++];
  for (int k = 0; k < 3; ++k) s->commanded.force[k] = in[i++];
  for (int k = 0; k < 3; ++k) s->commanded.torque[k] = in[i++];
  for (int k = 0; k < 3; ++k) s->delivered.force[k] = in[i++];
  for (int k = 0; k < 3; ++k) s->delivered.torque[k] = in[i++];
  for (int k = 0; k < 2; ++k) s->load[k] = in[i++];
}

// A recorded sample obeys the live device state's bounds (physical_bounds.h).
constexpr double kMaxRecordedTime = kMaxDeviceTime;
constexpr double kMaxRecordedPosition = kMaxDevicePosition;
constexpr double kMaxRecordedSpeed = kMaxDeviceSpeed;
constexpr double kMaxRecordedAngularSpeed = kMaxDeviceAngularSpeed;
constexpr double kMaxRecordedForce = kMaxDeviceForce;

double ColumnBound(int column) {
  const std::string unit = kColumns[column].unit;
  if (unit == "s") return kMaxRecordedTime;
  if (unit == "m") return kMaxRecordedPosition;
  if (unit == "1") return kMaxRecordedForce;  // quaternion parts: the unit-length check is exact
  if (unit == "m/s") return kMaxRecordedSpeed;
  if (unit == "rad/s") return kMaxRecordedAngularSpeed;
  return kMaxRecordedForce;
}

// A quaternion written from a rotation is unit to ~1e-16; 1e-9 leaves room for hand-made files
// while catching a column mix-up.
constexpr double kUnitTolerance = 1e-9;

std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) fields.push_back(line.substr(i, j - i));
    i = j;
  }
  return fields;
}

std::string Expected(int column) {
  return std::string(kColumns[column].name) + "_" + kColumns[column].unit;
}

}  // namespace

RecordingError::RecordingError(std::filesystem::path file, int line, std::string reason)
    : UserError(file.string() + ":" + std::to_string(line) + ": " + reason),
      file_(std::move(file)),
      line_(line),
      reason_(std::move(reason)) {}

RecordingError::~RecordingError() = default;

const std::vector<std::string>& RecordingColumns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> out;
    for (int c = 0; c < kColumnCount; ++c) out.push_back(Expected(c));
    return out;
  }();
  return columns;
}

RecordingWriter::RecordingWriter(std::filesystem::path file, const RecordingInfo& info)
    : file_(std::move(file)) {
  if (info.device_model.find('\n') != std::string::npos) {
    throw UserError("recording " + file_.string() + ": device model contains a line break");
  }
  out_.open(file_, std::ios::binary | std::ios::trunc);
  if (!out_) throw UserError("cannot write recording " + file_.string());
  out_ << kFormatLine << ' ' << kRecordingFormatVersion << '\n';
  if (!info.device_model.empty()) out_ << "# device: " << info.device_model << '\n';
  for (int c = 0; c < kColumnCount; ++c) out_ << (c ? " " : "") << Expected(c);
  out_ << '\n';
}

RecordingWriter::~RecordingWriter() = default;

void RecordingWriter::Append(const RecordedSample& s) {
  double fields[kColumnCount - 1];
  Flatten(s, fields);
  for (double v : fields) {
    if (!std::isfinite(v)) {
      throw UserError("recording " + file_.string() + ": sample " + std::to_string(count_) +
                      " holds a non-finite value; nothing written");
    }
  }
  if (count_ > 0 && !(s.time > last_time_)) {
    throw UserError("recording " + file_.string() + ": sample " + std::to_string(count_) +
                    " does not come after the previous one in time; nothing written");
  }
  char buffer[64];
  int f = 0;
  for (int c = 0; c < kColumnCount; ++c) {
    if (c) line_ += ' ';
    std::to_chars_result r;
    if (c == kButtonsColumn) {
      r = std::to_chars(buffer, buffer + sizeof(buffer), s.buttons);
    } else {
      r = std::to_chars(buffer, buffer + sizeof(buffer), fields[f++]);
    }
    line_.append(buffer, r.ptr);
  }
  line_ += '\n';
  // Written in blocks of about 1 MiB: memory stays bounded however long the recording.
  if (line_.size() > (std::size_t{1} << 20)) Flush();
  last_time_ = s.time;
  ++count_;
}

void RecordingWriter::Flush() {
  out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
  line_.clear();
  if (!out_) throw UserError("failed writing recording " + file_.string() + " (disk full?)");
}

void RecordingWriter::Finish() {
  line_ += kEndPrefix + std::to_string(count_) + " samples\n";
  Flush();
  out_.close();
  if (!out_) throw UserError("failed writing recording " + file_.string() + " (disk full?)");
}

void WriteRecording(const std::filesystem::path& file, const RecordingInfo& info,
                    std::span<const RecordedSample> samples) {
  std::filesystem::path temporary = file;
  temporary += ".partial";
  try {
    RecordingWriter writer(temporary, info);
    for (const RecordedSample& s : samples) writer.Append(s);
    writer.Finish();
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw UserError("cannot move recording into place at " + file.string());
  }
}

Recording ReadRecording(const std::filesystem::path& file) {
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  const int open_error = errno;
  if (!in) throw RecordingError(file, 0, "cannot open the recording: " + OsReason(open_error));
  std::stringstream whole;
  whole << in.rdbuf();
  const std::string text = NormalizeLineEndings(whole.str());

  Recording recording;
  int line_number = 0;
  std::size_t pos = 0;
  bool header_seen = false;
  bool end_seen = false;
  auto fail = [&](const std::string& reason) -> void {
    throw RecordingError(file, line_number, reason);
  };
  if (text.empty()) {
    line_number = 1;
    fail("empty file: expected '# fitfeel-recording 2'");
  }
  while (pos < text.size()) {
    ++line_number;
    const std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) {
      fail("truncated: the last line has no end of line");
    }
    std::string line = text.substr(pos, eol - pos);
    pos = eol + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (end_seen) fail("text after the end line");
    if (line_number == 1) {
      const std::vector<std::string> f = SplitFields(line);
      if (f.size() != 3 || f[0] != "#" || f[1] != "fitfeel-recording") {
        fail("not a fitfeel recording: expected '# fitfeel-recording 2', found '" + line + "'");
      }
      if (f[2] != std::to_string(kRecordingFormatVersion)) {
        fail("unsupported recording format version '" + f[2] + "' (this build reads " +
             std::to_string(kRecordingFormatVersion) + ")");
      }
      continue;
    }
    if (line.rfind(kEndPrefix, 0) == 0) {
      if (!header_seen) fail("end line before the column header");
      const std::vector<std::string> f = SplitFields(line.substr(std::string(kEndPrefix).size()));
      std::size_t count = 0;
      const auto r = f.empty() ? std::from_chars_result{nullptr, std::errc::invalid_argument}
                               : std::from_chars(f[0].data(), f[0].data() + f[0].size(), count);
      if (f.size() != 2 || f[1] != "samples" || r.ec != std::errc() ||
          r.ptr != f[0].data() + f[0].size()) {
        fail("malformed end line: expected '# end: <count> samples'");
      }
      if (count != recording.samples.size()) {
        fail("end line announces " + std::to_string(count) + " samples but " +
             std::to_string(recording.samples.size()) + " were read");
      }
      end_seen = true;
      continue;
    }
    if (!line.empty() && line[0] == '#') {
      if (header_seen) fail("comment line among the samples");
      const std::string body = line.substr(1);
      const std::size_t colon = body.find(':');
      if (colon == std::string::npos) fail("malformed metadata line: expected '# key: value'");
      std::string key = body.substr(0, colon);
      std::string value = body.substr(colon + 1);
      auto trim = [](std::string& s) {
        while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.erase(s.begin());
        while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.pop_back();
      };
      trim(key);
      trim(value);
      if (key == "device") recording.info.device_model = value;
      continue;  // unknown metadata keys are kept for newer writers and ignored
    }
    const std::vector<std::string> f = SplitFields(line);
    if (!header_seen) {
      if (f.size() != static_cast<std::size_t>(kColumnCount)) {
        fail("column header has " + std::to_string(f.size()) + " columns, expected " +
             std::to_string(kColumnCount));
      }
      for (int c = 0; c < kColumnCount; ++c) {
        const std::string& name = f[c];
        const std::string want_name = kColumns[c].name;
        const std::size_t split = want_name.size();
        const bool name_matches = name.compare(0, split, want_name) == 0;
        if (name == want_name || (name_matches && name.size() == split)) {
          fail("column " + std::to_string(c + 1) + " '" + name + "' has no unit (expected '" +
               Expected(c) + "')");
        }
        if (!name_matches || name[split] != '_') {
          if (name.find('_') == std::string::npos) {
            fail("column " + std::to_string(c + 1) + " '" + name + "' has no unit (expected '" +
                 Expected(c) + "')");
          }
          fail("column " + std::to_string(c + 1) + " is '" + name + "', expected '" + Expected(c) +
               "'");
        }
        const std::string unit = name.substr(split + 1);
        if (unit != kColumns[c].unit) {
          fail("column " + std::to_string(c + 1) + " '" + name + "' is in '" + unit +
               "', expected '" + kColumns[c].unit + "'");
        }
      }
      header_seen = true;
      continue;
    }
    if (f.size() != static_cast<std::size_t>(kColumnCount)) {
      fail("sample has " + std::to_string(f.size()) + " fields, expected " +
           std::to_string(kColumnCount));
    }
    double values[kColumnCount - 1];
    RecordedSample sample;
    int v = 0;
    for (int c = 0; c < kColumnCount; ++c) {
      const char* begin = f[c].data();
      const char* end = begin + f[c].size();
      if (c == kButtonsColumn) {
        const auto r = std::from_chars(begin, end, sample.buttons);
        if (r.ec != std::errc() || r.ptr != end) {
          fail("field " + std::to_string(c + 1) + " (" + Expected(c) + ") '" + f[c] +
               "' is not an unsigned integer");
        }
        continue;
      }
      double value = 0.0;
      const auto r = std::from_chars(begin, end, value);
      if (r.ec != std::errc() || r.ptr != end || !std::isfinite(value)) {
        fail("field " + std::to_string(c + 1) + " (" + Expected(c) + ") '" + f[c] +
             "' is not a finite number");
      }
      if (!(std::abs(value) <= ColumnBound(c))) {
        char bound[32];
        std::snprintf(bound, sizeof bound, "%g", ColumnBound(c));
        fail("field " + std::to_string(c + 1) + " (" + Expected(c) + ") '" + f[c] +
             "' is outside physical sense (|value| <= " + bound + " " + kColumns[c].unit + ")");
      }
      values[v++] = value;
    }
    Unflatten(values, &sample);
    if (std::abs(sample.orientation.squaredNorm() - 1.0) > kUnitTolerance) {
      fail("orientation quaternion is not of unit length");
    }
    if (!recording.samples.empty() && !(sample.time > recording.samples.back().time)) {
      fail("time " + f[0] + " s does not come after the previous sample's");
    }
    recording.samples.push_back(sample);
  }
  if (!header_seen) fail("truncated: no column header");
  if (!end_seen) {
    fail("truncated: no '# end: <count> samples' line after " +
         std::to_string(recording.samples.size()) + " samples");
  }
  return recording;
}

}  // namespace fitfeel
