#include "framework/scenario/measurement_file.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <istream>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/os_reason.h"
#include "framework/core/path_check.h"
#include "framework/core/quantity.h"

namespace fitfeel::scenario {
namespace {

namespace fs = std::filesystem;

struct Column {
  std::string name;
  double scale = 1.0;  // file unit -> SI
  int index = 0;       // which cell of a line
};

struct Cell {
  std::string_view text;
  int position = 0;
};

constexpr std::size_t kQuotedChars = 40;

// `text` quoted for a message: control bytes (a NUL would end the message where it is printed)
// escaped as \xNN, and at most kQuotedChars characters, then "..." (never cut inside a UTF-8
// sequence).
std::string Quoted(std::string_view text) {
  std::string out = "'";
  std::size_t shown = 0, k = 0;
  for (; k < text.size() && shown < kQuotedChars; ++shown) {
    const auto byte = static_cast<unsigned char>(text[k]);
    if (byte < 0x20 || byte == 0x7f) {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
      ++k;
      continue;
    }
    std::size_t length = 1;  // one character: its lead byte and continuation bytes
    while (k + length < text.size() &&
           (static_cast<unsigned char>(text[k + length]) & 0xc0) == 0x80 && length < 4) {
      ++length;
    }
    out.append(text.substr(k, length));
    k += length;
  }
  out += k < text.size() ? "'..." : "'";
  return out;
}

std::string_view TrimBlanks(std::string_view s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

// The comma-separated cells of `line`, trimmed, with their 1-based columns, into `cells`.
void SplitCells(std::string_view line, std::vector<Cell>* cells) {
  cells->clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(line.find(',', start), line.size());
    const std::string_view raw = line.substr(start, end - start);
    const std::size_t lead = raw.find_first_not_of(" \t\r");
    cells->push_back({TrimBlanks(raw),
                      static_cast<int>(start + (lead == std::string_view::npos ? 0 : lead)) + 1});
    if (end == line.size()) break;
    start = end + 1;
  }
}

class Reader {
 public:
  Reader(fs::path file, const ConfigNode& key) : file_(std::move(file)), key_(key) {}

  [[noreturn]] void Fail(int line, int column, const std::string& expected,
                         const std::string& found) const {
    throw ScenarioError({file_.string(), line, column}, key_.path(), expected, found);
  }

  const fs::path& file() const { return file_; }

 private:
  fs::path file_;
  const ConfigNode& key_;
};

// The lines of a stream, read a block at a time: a line ends at LF, CR LF or a lone CR (line
// numbers are those an editor shows), and none may exceed kMaxMeasurementLineBytes, so memory
// stays a block and a line whatever the file holds.
class LineReader {
 public:
  LineReader(std::istream& in, const Reader& reader) : in_(in), reader_(reader) {}

  // The next line without its ending, valid until the next call; false at the end.
  bool Next(std::string_view* line) {
    line_.clear();
    bool any = false;  // a byte or a line ending since the last line
    while (true) {
      if (position_ == block_.size() && !Fill()) break;
      if (after_cr_) {
        after_cr_ = false;
        if (block_[position_] == '\n') {
          ++position_;
          continue;
        }
      }
      any = true;
      const char* begin = block_.data() + position_;
      const char* end = block_.data() + block_.size();
      const char* stop = begin;
      while (stop != end && *stop != '\n' && *stop != '\r') ++stop;
      const auto taken = static_cast<std::size_t>(stop - begin);
      if (line_.size() + taken > kMaxMeasurementLineBytes) {
        line_.append(begin, std::min(taken, kQuotedChars + 1));
        reader_.Fail(number_ + 1, 1,
                     "a line of at most " + std::to_string(kMaxMeasurementLineBytes) +
                         " bytes (one sample, or a comment)",
                     "a longer line: " + Quoted(line_));
      }
      line_.append(begin, taken);
      position_ += taken;
      if (stop != end) {
        after_cr_ = *stop == '\r';
        ++position_;
        ++number_;
        *line = line_;
        return true;
      }
    }
    if (in_.bad()) reader_.Fail(number_ + 1, 1, "a readable file", "a read error");
    if (!any) return false;
    ++number_;
    *line = line_;
    return true;
  }

  int number() const { return number_; }

 private:
  bool Fill() {
    block_.resize(kBlockBytes);
    in_.read(block_.data(), static_cast<std::streamsize>(block_.size()));
    block_.resize(static_cast<std::size_t>(in_.gcount()));
    position_ = 0;
    return !block_.empty();
  }

  static constexpr std::size_t kBlockBytes = std::size_t{1} << 16;
  std::istream& in_;
  const Reader& reader_;
  std::string block_;
  std::size_t position_ = 0;
  std::string line_;
  bool after_cr_ = false;
  int number_ = 0;
};

// The columns each kind reads, with their dimension; radius and deviation are alternatives.
const std::map<std::string, Dimension>& KnownColumns(MeasurementKind kind) {
  static const std::map<std::string, Dimension> traces = {{"height", Dimension::kLength},
                                                          {"angle", Dimension::kAngle},
                                                          {"radius", Dimension::kLength},
                                                          {"deviation", Dimension::kLength}};
  static const std::map<std::string, Dimension> points = {
      {"x", Dimension::kLength}, {"y", Dimension::kLength}, {"z", Dimension::kLength}};
  return kind == MeasurementKind::kPoints ? points : traces;
}

std::string ExpectedKind(MeasurementKind kind) {
  return kind == MeasurementKind::kPoints
             ? "a header of the columns x, y, z, each as 'name [unit]' (e.g. 'x [mm]')"
             : "a header of the columns height, angle and radius or deviation, each as "
               "'name [unit]' (e.g. 'angle [deg]')";
}

std::map<std::string, Column> ParseHeader(std::string_view line, int number,
                                          MeasurementKind kind, const Reader& reader) {
  const auto& known = KnownColumns(kind);
  std::map<std::string, Column> columns;
  std::vector<Cell> cells;
  SplitCells(line, &cells);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const Cell& cell = cells[k];
    const std::size_t open = cell.text.find('[');
    const std::size_t close = cell.text.rfind(']');
    if (open == std::string_view::npos || close != cell.text.size() - 1 || close < open) {
      reader.Fail(number, cell.position, ExpectedKind(kind), Quoted(cell.text));
    }
    const std::string name(TrimBlanks(cell.text.substr(0, open)));
    const std::string unit(TrimBlanks(cell.text.substr(open + 1, close - open - 1)));
    const auto it = known.find(name);
    if (it == known.end()) {
      reader.Fail(number, cell.position, ExpectedKind(kind), "a column " + Quoted(name));
    }
    if (columns.count(name) != 0) {
      reader.Fail(number, cell.position, "each column once", "'" + name + "' again");
    }
    double scale = 0.0;
    try {
      scale = ParseQuantity("1 " + unit, it->second);
    } catch (const std::invalid_argument&) {
      reader.Fail(number, cell.position,
                  "a unit of " + DescribeDimension(it->second) + " for '" + name + "'",
                  Quoted(unit));
    }
    columns[name] = {name, scale, static_cast<int>(k)};
  }
  auto need = [&](const char* name) {
    if (columns.count(name) == 0) {
      reader.Fail(number, 1, ExpectedKind(kind), std::string("no column '") + name + "'");
    }
  };
  if (kind == MeasurementKind::kPoints) {
    need("x");
    need("y");
    need("z");
  } else {
    need("height");
    need("angle");
    const bool radius = columns.count("radius") != 0, deviation = columns.count("deviation") != 0;
    if (radius == deviation) {
      reader.Fail(number, 1, "one of the columns radius or deviation",
                  radius ? "both" : "neither");
    }
  }
  return columns;
}

double Normalised(double angle) {
  const double two_pi = 2.0 * std::numbers::pi;
  double a = std::fmod(angle, two_pi);
  if (a < 0.0) a += two_pi;
  return a >= two_pi ? 0.0 : a;
}

}  // namespace

MeasuredSurface ReadMeasurement(const fs::path& file, MeasurementKind kind, double nominal_radius,
                                const ConfigNode& key) {
  const std::string wanted =
      "a readable " + std::string(MeasurementKindName(kind)) + " measurement file (CSV)";
  std::error_code ec;
  // A device or a pipe (/dev/zero) would never end; a regular file has a size to bound. Refused in
  // the OS's words (a symlink loop is a loop).
  if (const std::string why = WhyNotReadableFile(file); !why.empty()) {
    key.Fail(wanted, "'" + file.string() + "', which " + why);
  }
  if (fs::file_size(file, ec) > kMaxMeasurementBytes) {
    key.Fail(wanted + " of at most " + std::to_string(kMaxMeasurementBytes >> 20) + " MiB",
             "'" + file.string() + "' of " + std::to_string(fs::file_size(file, ec) >> 20) + " MiB");
  }
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  const int open_error = errno;
  if (!in) key.Fail(wanted, "'" + file.string() + "', which cannot be read: " + OsReason(open_error));
  const Reader reader(file, key);
  MeasuredSurface m;
  m.kind = kind;
  m.file = file;
  m.key_location = key.location();
  m.key_path = key.path();
  LineReader lines(in, reader);
  std::string_view line;
  std::optional<std::map<std::string, Column>> header;
  std::vector<std::int32_t> line_of;  // per sample, for the errors found after reading
  std::vector<Cell> cells;
  // The header's columns in the order a sample reads them: x, y, z; or height, angle, radius or
  // deviation.
  std::vector<Column> read;
  const std::string coordinate = "a coordinate within 10 m";
  const std::string near_nominal = "a radius within 1 mm of the nominal " +
                                   FormatQuantity(nominal_radius, Dimension::kLength) +
                                   " (a wrong unit or frame?)";
  while (lines.Next(&line)) {
    const int number = lines.number();
    const std::string_view trimmed = TrimBlanks(line);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    if (!header) {
      header = ParseHeader(line, number, kind, reader);
      for (const char* name : kind == MeasurementKind::kPoints
                                  ? std::vector<const char*>{"x", "y", "z"}
                                  : std::vector<const char*>{"height", "angle", "radius",
                                                             "deviation"}) {
        if (header->count(name) != 0) read.push_back(header->at(name));
      }
      continue;
    }
    // Counted before the cells are split: a line of many cells costs nothing.
    const auto count = static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
    if (count != header->size()) {
      reader.Fail(number, 1, std::to_string(header->size()) + " cells, as the header",
                  std::to_string(count));
    }
    if (m.value.size() == kMaxMeasurementSamples) {
      reader.Fail(number, 1,
                  "at most " + std::to_string(kMaxMeasurementSamples) +
                      " samples (the cells of the finest grid a part gets)",
                  "a sample beyond them");
    }
    SplitCells(line, &cells);
    auto value = [&](std::size_t column) {
      const Column& c = read[column];
      const Cell& cell = cells[static_cast<std::size_t>(c.index)];
      double x = 0.0;
      const auto r = std::from_chars(cell.text.data(), cell.text.data() + cell.text.size(), x);
      if (cell.text.empty() || r.ec != std::errc() ||
          r.ptr != cell.text.data() + cell.text.size() || !std::isfinite(x)) {
        reader.Fail(number, cell.position, "a finite number in column '" + c.name + "'",
                    Quoted(cell.text));
      }
      return std::pair<double, int>(x * c.scale, cell.position);
    };
    auto bounded = [&](std::size_t column, double bound, const std::string& what) {
      const auto [x, position] = value(column);
      if (!(std::abs(x) <= bound)) {
        reader.Fail(number, position, what, FormatQuantity(x, Dimension::kLength));
      }
      return x;
    };
    if (kind == MeasurementKind::kPoints) {
      const double x = bounded(0, kMaxMeasuredCoordinate, coordinate);
      const double y = bounded(1, kMaxMeasuredCoordinate, coordinate);
      const double z = bounded(2, kMaxMeasuredCoordinate, coordinate);
      const double r = std::hypot(x, z);
      if (!(std::abs(r - nominal_radius) <= kMaxMeasuredDeviation)) {
        reader.Fail(number, cells[static_cast<std::size_t>(read[0].index)].position,
                    near_nominal,
                    "a point at radius " + FormatQuantity(r, Dimension::kLength));
      }
      m.height.push_back(y);
      m.angle.push_back(Normalised(std::atan2(z, x)));
      m.value.push_back(r);
      m.absolute = true;
    } else {
      m.height.push_back(bounded(0, kMaxMeasuredCoordinate, coordinate));
      const auto [angle, angle_at] = value(1);
      if (!(std::abs(angle) <= 1000.0)) {
        reader.Fail(number, angle_at, "an angle within 1000 rad", std::to_string(angle) + " rad");
      }
      m.angle.push_back(Normalised(angle));
      if (read[2].name == "radius") {
        const auto [r, at] = value(2);
        if (!(std::abs(r - nominal_radius) <= kMaxMeasuredDeviation)) {
          reader.Fail(number, at, near_nominal, FormatQuantity(r, Dimension::kLength));
        }
        m.value.push_back(r);
        m.absolute = true;
      } else {
        m.value.push_back(
            bounded(2, kMaxMeasuredDeviation, "a deviation within 1 mm (a wrong unit?)"));
      }
    }
    line_of.push_back(number);
  }
  const int number = lines.number();
  if (!header) reader.Fail(number, 1, ExpectedKind(kind), "no header");
  if (m.value.empty()) reader.Fail(number, 1, "at least one sample after the header", "none");

  // Traces: group, check distinct samples and enough of them.
  if (kind != MeasurementKind::kPoints) {
    const bool roundness = kind == MeasurementKind::kRoundness;
    const std::vector<double>& key_of = roundness ? m.height : m.angle;
    const std::vector<double>& along = roundness ? m.angle : m.height;
    // 32-bit indices: kMaxMeasurementSamples fit.
    std::vector<std::uint32_t> order(m.value.size());
    for (std::size_t s = 0; s < order.size(); ++s) order[s] = static_cast<std::uint32_t>(s);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return key_of[a] != key_of[b] ? key_of[a] < key_of[b] : along[a] < along[b];
    });
    const std::size_t least = roundness ? 3 : 2;
    std::size_t first = 0;
    for (std::size_t k = 0; k <= order.size(); ++k) {
      const bool ends = k == order.size() || key_of[order[k]] != key_of[order[first]];
      if (ends) {
        ++m.traces;
        if (k - first < least) {
          reader.Fail(line_of[order[first]], 1,
                      std::string("at least ") + std::to_string(least) + " samples in each " +
                          (roundness ? "roundness trace (one height)"
                                     : "straightness trace (one angle)"),
                      std::to_string(k - first));
        }
        first = k;
        continue;
      }
      if (k > first && along[order[k]] == along[order[k - 1]]) {
        const std::uint32_t later = std::max(order[k], order[k - 1]);
        reader.Fail(line_of[later], 1, "each sample of a trace once",
                    std::string("a repeated ") + (roundness ? "angle" : "height") + " (line " +
                        std::to_string(line_of[std::min(order[k], order[k - 1])]) + ")");
      }
    }
  } else if (m.value.size() < 3) {
    reader.Fail(number, 1, "at least 3 points", std::to_string(m.value.size()));
  }
  return m;
}

}  // namespace fitfeel::scenario
