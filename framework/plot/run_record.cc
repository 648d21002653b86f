#include "framework/plot/run_record.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <map>
#include <system_error>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/core/os_reason.h"
#include "framework/core/path_check.h"

namespace fitfeel::plot {
namespace fs = std::filesystem;

namespace {

using Json = nlohmann::json;

std::string_view TrimField(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  text = text.substr(first, last - first + 1);
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
    text = text.substr(1, text.size() - 2);
  }
  return text;
}

// Fields of one CSV line with their 1-based starting columns. The trace contract has no quoted
// commas (stage names are single words), so a plain split is the whole grammar.
std::vector<std::pair<std::string_view, int>> SplitCsv(std::string_view line) {
  std::vector<std::pair<std::string_view, int>> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    fields.emplace_back(TrimField(line.substr(start, end - start)), static_cast<int>(start) + 1);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

const Json& Require(const Json& object, const std::string& key, const std::string& path,
                    const fs::path& file) {
  if (!object.is_object() || !object.contains(key)) {
    throw UserError(file.string() + ": " + path + key + ": expected a value, found nothing");
  }
  return object.at(key);
}

double RequireNumber(const Json& object, const std::string& key, const std::string& path,
                     const fs::path& file) {
  const Json& value = Require(object, key, path, file);
  if (!value.is_number()) {
    throw UserError(file.string() + ": " + path + key + ": expected a number, found " +
                    value.dump());
  }
  return value.get<double>();
}

ResistanceStats ReadStats(const Json& root, const std::string& key, const fs::path& file) {
  const Json& stats = Require(root, key, "", file);
  if (!stats.is_object()) {
    throw UserError(file.string() + ": " + key + ": expected {mean, min, max}, found " +
                    stats.dump());
  }
  return {RequireNumber(stats, "mean", key + ".", file),
          RequireNumber(stats, "min", key + ".", file),
          RequireNumber(stats, "max", key + ".", file)};
}

}  // namespace

RunSummary LoadSummary(const fs::path& file) {
  errno = 0;
  std::ifstream in(file);
  const int open_error = errno;
  if (!in) {
    throw UserError("cannot read the run summary '" + file.string() + "': " + OsReason(open_error));
  }
  Json root;
  try {
    root = Json::parse(in);
  } catch (const Json::parse_error& e) {
    throw UserError(file.string() + ": not valid JSON: " + e.what());
  }
  if (!root.is_object()) throw UserError(file.string() + ": expected a JSON object");
  RunSummary summary;
  const Json& scenario = Require(root, "scenario", "", file);
  if (!scenario.is_string()) {
    throw UserError(file.string() + ": scenario: expected a string, found " + scenario.dump());
  }
  summary.scenario = scenario.get<std::string>();
  if (root.contains("law") && root.at("law").is_string()) summary.law = root.at("law");
  for (const char* key : {"scenario_file", "scenario_path"}) {
    if (root.contains(key) && root.at(key).is_string()) {
      summary.scenario_file = root.at(key).get<std::string>();
      break;
    }
  }
  if (root.contains("seed") && root.at("seed").is_number_unsigned()) {
    summary.seed = root.at("seed").get<std::uint64_t>();
  }
  if (root.contains("grid") && root.at("grid").is_object()) {
    const Json& grid = root.at("grid");
    const auto read = [&](const char* part) -> std::optional<std::pair<int, int>> {
      if (!grid.contains(part)) return std::nullopt;
      const Json& g = grid.at(part);
      if (!g.is_object() || !g.contains("rows") || !g.contains("columns") ||
          !g.at("rows").is_number_integer() || !g.at("columns").is_number_integer()) {
        throw UserError(file.string() + ": grid." + part +
                        ": expected {rows, columns} integers, found " + g.dump());
      }
      return std::make_pair(g.at("rows").get<int>(), g.at("columns").get<int>());
    };
    summary.inner_grid = read("inner");
    summary.outer_grid = read("outer");
  }
  summary.axial = ReadStats(root, "axial_resistance_N", file);
  summary.radial = ReadStats(root, "radial_resistance_N", file);
  return summary;
}

ConstrainedTrace LoadConstrainedTrace(const fs::path& file) {
  errno = 0;
  std::ifstream in(file);
  const int open_error = errno;
  if (!in)
    throw UserError("cannot read the trace '" + file.string() + "': " + OsReason(open_error));
  std::string header_line;
  if (!std::getline(in, header_line)) throw UserError(file.string() + ": empty file, no header");
  std::map<std::string, std::size_t, std::less<>> index;
  const auto header = SplitCsv(header_line);
  for (std::size_t k = 0; k < header.size(); ++k) index.emplace(std::string(header[k].first), k);
  const std::vector<std::string> needed = {"t_s", "stage", "depth_mm", "fx_N", "fy_N", "fz_N"};
  std::string missing;
  for (const auto& name : needed) {
    if (!index.count(name)) missing += (missing.empty() ? "" : ", ") + name;
  }
  if (!missing.empty()) {
    throw UserError(
        file.string() + ":1: header lacks the column(s) " + missing +
        " (a trace needs t_s, stage, depth_mm, fx_N, fy_N, fz_N); found: " + header_line);
  }
  const std::size_t stage = index.at("stage");
  const std::size_t t = index.at("t_s"), depth = index.at("depth_mm");
  const std::size_t fx = index.at("fx_N"), fy = index.at("fy_N"), fz = index.at("fz_N");

  // The pose columns are optional: all three or none.
  const bool has_pose = index.count("x_mm") && index.count("z_mm") && index.count("angle_rad");
  const std::size_t x = has_pose ? index.at("x_mm") : 0, z = has_pose ? index.at("z_mm") : 0;
  const std::size_t angle = has_pose ? index.at("angle_rad") : 0;
  const bool has_offset = index.count("offset_x_um") && index.count("offset_z_um");
  const std::size_t offset_x = has_offset ? index.at("offset_x_um") : 0;
  const std::size_t offset_z = has_offset ? index.at("offset_z_um") : 0;
  const bool has_torque = index.count("tx_Nm") && index.count("ty_Nm") && index.count("tz_Nm");
  const std::size_t tx = has_torque ? index.at("tx_Nm") : 0;
  const std::size_t ty = has_torque ? index.at("ty_Nm") : 0;
  const std::size_t tz = has_torque ? index.at("tz_Nm") : 0;
  const bool has_screw = index.count("torque_Nm") && index.count("preload_N");
  const std::size_t screw_torque = has_screw ? index.at("torque_Nm") : 0;
  const std::size_t preload = has_screw ? index.at("preload_N") : 0;
  const bool has_seated = has_screw && index.count("seated");
  const std::size_t seated = has_seated ? index.at("seated") : 0;

  ConstrainedTrace trace;
  std::string line;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (TrimField(line).empty()) continue;
    const auto fields = SplitCsv(line);
    if (fields.size() != header.size()) {
      throw UserError(file.string() + ":" + std::to_string(line_number) + ": expected " +
                      std::to_string(header.size()) + " fields as in the header, found " +
                      std::to_string(fields.size()));
    }
    if (fields[stage].first != "constrained") continue;
    const auto number = [&](std::size_t column) {
      const auto [text, at] = fields[column];
      double value = 0.0;
      const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
      if (result.ec != std::errc() || result.ptr != text.data() + text.size() || text.empty()) {
        throw UserError(file.string() + ":" + std::to_string(line_number) + ":" +
                        std::to_string(at) + ": " + std::string(header[column].first) +
                        ": expected a number, found '" + std::string(text) + "'");
      }
      return value;
    };
    trace.t_s.push_back(number(t));
    trace.depth_mm.push_back(number(depth));
    trace.fx_N.push_back(number(fx));
    trace.fy_N.push_back(number(fy));
    trace.fz_N.push_back(number(fz));
    if (has_pose) {
      trace.x_mm.push_back(number(x));
      trace.z_mm.push_back(number(z));
      trace.angle_rad.push_back(number(angle));
    }
    if (has_offset) {
      trace.offset_x_um.push_back(number(offset_x));
      trace.offset_z_um.push_back(number(offset_z));
    }
    if (has_torque) {
      trace.tx_Nm.push_back(number(tx));
      trace.ty_Nm.push_back(number(ty));
      trace.tz_Nm.push_back(number(tz));
    }
    if (has_screw) {
      trace.torque_Nm.push_back(number(screw_torque));
      trace.preload_N.push_back(number(preload));
    }
    if (has_seated) {
      trace.seated.push_back(number(seated));
    }
  }
  if (trace.t_s.empty()) {
    throw UserError(file.string() +
                    ": no row in the constrained stage (column stage = "
                    "'constrained'); nothing to plot");
  }
  return trace;
}

RunRecord LoadRun(const fs::path& dir) {
  if (const std::string why = WhyNotFolder(dir); !why.empty()) {
    throw UserError("run folder '" + dir.string() + "' " + why);
  }
  for (const char* name : {"summary.json", "trace.csv"}) {
    const std::string why = WhyNotReadableFile(dir / name);
    if (why == kDoesNotExist) {
      throw UserError("run folder '" + dir.string() + "' has no " + name +
                      " (write it with `fitfeel run`, outputs [trace, summary])");
    }
    if (!why.empty()) throw UserError("'" + (dir / name).string() + "' " + why);
  }
  RunRecord record;
  record.dir = dir;
  record.summary = LoadSummary(dir / "summary.json");
  record.trace = LoadConstrainedTrace(dir / "trace.csv");
  return record;
}

}  // namespace fitfeel::plot
