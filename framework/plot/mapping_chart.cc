#include "framework/plot/mapping_chart.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/core/os_reason.h"
#include "framework/plot/render.h"

namespace fitfeel::plot {
namespace fs = std::filesystem;
namespace {

using Json = nlohmann::json;

Json ReadJson(const fs::path& file) {
  errno = 0;
  std::ifstream in(file);
  const int open_error = errno;
  if (!in) {
    throw UserError("cannot read the run summary '" + file.string() + "': " + OsReason(open_error));
  }
  try {
    Json root = Json::parse(in);
    if (!root.is_object()) throw UserError(file.string() + ": expected a JSON object");
    return root;
  } catch (const Json::parse_error& e) {
    throw UserError(file.string() + ": not valid JSON: " + e.what());
  }
}

double Number(const Json& object, const std::string& key, const std::string& path,
              const fs::path& file) {
  if (!object.is_object() || !object.contains(key) || !object.at(key).is_number()) {
    throw UserError(file.string() + ": " + path + key + ": expected a number, found " +
                    (object.is_object() && object.contains(key) ? object.at(key).dump()
                                                                : std::string("nothing")));
  }
  return object.at(key).get<double>();
}

ForceMapping MappingOf(const Json& root, const fs::path& file) {
  const Json* safety = root.contains("safety") ? &root.at("safety") : nullptr;
  if (safety == nullptr || !safety->is_object() || !safety->contains("force_mapping")) {
    throw UserError(file.string() +
                    ": safety.force_mapping: the run's summary records no force mapping (a run "
                    "of a fitfeel without one, or not a run's summary); run the scene again");
  }
  const Json& m = safety->at("force_mapping");
  const std::string path = "safety.force_mapping.";
  const std::string kind = m.is_object() && m.contains("kind") && m.at("kind").is_string()
                               ? m.at("kind").get<std::string>()
                               : std::string();
  try {
    if (kind == "perceptual") {
      return ForceMapping::Perceptual(Number(m, "knee_N", path, file),
                                      Number(m, "scene_top_N", path, file),
                                      Number(m, "device_top_N", path, file));
    }
    if (kind == "linear") return ForceMapping::Linear(Number(m, "scale", path, file));
  } catch (const UserError& e) {
    const std::string what = e.what();
    if (what.rfind(file.string(), 0) == 0) throw;
    throw UserError(file.string() + ": " + path + " " + what);
  }
  throw UserError(file.string() + ": " + path +
                  "kind: expected \"linear\" or \"perceptual\", found " +
                  (m.is_object() && m.contains("kind") ? m.at("kind").dump() : "nothing"));
}

bool SameMapping(const ForceMapping& a, const ForceMapping& b) {
  auto near = [](double x, double y) {
    return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(x));
  };
  return a.kind() == b.kind() && near(a.scale(), b.scale()) && near(a.knee(), b.knee()) &&
         near(a.scene_top(), b.scene_top()) && near(a.device_top(), b.device_top());
}

// Labels go inside a data block between double quotes.
std::string DataLabel(const std::string& label) {
  std::string out;
  for (char c : label) out += c == '"' ? '\'' : (static_cast<unsigned char>(c) < 0x20 ? ' ' : c);
  return "\"" + out + "\"";
}

// Points within 2 % of each other in both forces, merged in order of first appearance.
std::vector<MappingPoint> Merged(const std::vector<MappingPoint>& points) {
  std::vector<MappingPoint> merged;
  auto close = [](double a, double b) { return std::abs(a - b) <= 0.02 * std::max(a, b); };
  for (const MappingPoint& p : points) {
    bool joined = false;
    for (MappingPoint& m : merged) {
      if (close(m.scene_N, p.scene_N) && close(m.device_N, p.device_N)) {
        m.label += ", " + p.label;
        joined = true;
        break;
      }
    }
    if (!joined) merged.push_back(p);
  }
  return merged;
}

std::string Body(const MappingChartData& data) {
  const ForceMapping& map = data.mapping;
  const bool perceptual = map.kind() == ForceMappingKind::kPerceptual;
  double x_max = perceptual ? 2.0 * map.scene_top() : 0.0;
  for (const MappingPoint& p : data.points) x_max = std::max(x_max, 2.0 * p.scene_N);
  if (!(x_max > 0.1)) x_max = 100.0;
  constexpr double kXMin = 0.01;
  std::ostringstream s;
  s << "reset\n$curve << EOD\n";
  const int n = 400;
  double y_max = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double f = kXMin * std::pow(x_max / kXMin, static_cast<double>(k) / n);
    const double mapped = map.Map(f);
    y_max = std::max(y_max, mapped);
    s << ShortestDecimal(f) << " " << ShortestDecimal(mapped) << "\n";
  }
  s << "EOD\n";
  std::vector<MappingPoint> points = Merged(data.points);
  std::sort(points.begin(), points.end(),
            [](const MappingPoint& a, const MappingPoint& b) { return a.scene_N < b.scene_N; });
  // The curve rises to the right: a label left of the middle reads to the right of its point,
  // one right of it to the left, both above, on an opaque box where the curve passes behind.
  const double middle = std::sqrt(kXMin * x_max);
  std::ostringstream left, right;
  for (const MappingPoint& p : points) {
    y_max = std::max(y_max, p.device_N);
    (p.scene_N < middle ? left : right)
        << ShortestDecimal(p.scene_N) << " " << ShortestDecimal(p.device_N) << " "
        << DataLabel(p.label) << "\n";
  }
  s << "$left << EOD\n" << left.str() << "EOD\n$right << EOD\n" << right.str() << "EOD\n";
  std::string title = "Force mapping: ";
  if (perceptual) {
    title += "perceptual, knee " + ShortestDecimal(map.knee()) + " N, exponent " +
             ShortestDecimal(std::round(map.exponent() * 1e4) / 1e4) + ", scene top " +
             ShortestDecimal(map.scene_top()) + " N -> device top " +
             ShortestDecimal(std::round(map.device_top() * 1e4) / 1e4) + " N";
  } else {
    title += "linear, " + ShortestDecimal(map.scale()) + " device N per scene N";
  }
  s << "set title " << QuoteForGnuplot(title);
  if (!data.device.empty()) s << " . \"\\n\" . " << QuoteForGnuplot("device: " + data.device);
  s << " font ',13'\n";
  s << "set lmargin 12\nset rmargin 8\n";
  s << "set grid xtics ytics mxtics lc rgb '#c8c8c8' lw 1 dt solid\n";
  s << "set logscale x\nset format x '%g'\n";
  s << "set xrange [" << ShortestDecimal(kXMin) << ":" << ShortestDecimal(x_max) << "]\n";
  s << "set yrange [0:" << ShortestDecimal(1.2 * (y_max > 0.0 ? y_max : 1.0)) << "]\n";
  s << "set xlabel 'scene force (N, log scale): the run`s mean axial resistance'\n";
  s << "set ylabel 'device force (N): the run`s mean delivered force'\n";
  s << "set key top left\n";
  s << "set style textbox opaque noborder margins 1,1\n";
  s << "plot $curve using 1:2 with lines lw 2 lc rgb '#3b528b' title 'mapping'";
  // gnuplot warns about an empty block: only the blocks that hold a point are drawn.
  bool titled = false;
  for (const auto& [block, labels] :
       {std::pair{"$left", "left offset 0.8,0.9"}, std::pair{"$right", "right offset -0.8,0.9"}}) {
    if ((block == std::string("$left") ? left : right).str().empty()) continue;
    s << ", " << block << " using 1:2 with points pt 7 ps 1.3 lc rgb '#b5367a' "
      << (titled ? "notitle" : "title 'runs (mean)'") << ", " << block
      << " using 1:2:3 with labels boxed " << labels << " font ',10' notitle";
    titled = true;
  }
  s << "\n";
  // A backquote stands for an apostrophe: gnuplot writes one as two inside single quotes.
  std::string body;
  for (char c : s.str()) body += c == '`' ? std::string("''") : std::string(1, c);
  return body;
}

}  // namespace

ForceMapping ReadForceMapping(const fs::path& summary_json) {
  return MappingOf(ReadJson(summary_json), summary_json);
}

MappingChartData LoadMappingRuns(const std::vector<fs::path>& dirs) {
  if (dirs.empty()) throw UserError("plot mapping: no run folders");
  MappingChartData data;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const fs::path& dir = dirs[i];
    if (!fs::is_directory(dir)) {
      throw UserError("run folder '" + dir.string() + "' does not exist");
    }
    const fs::path file = dir / "summary.json";
    const Json root = ReadJson(file);
    const ForceMapping mapping = MappingOf(root, file);
    if (i == 0) {
      data.mapping = mapping;
      const Json& safety = root.at("safety");
      if (safety.contains("device_model") && safety.at("device_model").is_string()) {
        data.device = safety.at("device_model").get<std::string>();
      }
    } else if (!SameMapping(mapping, data.mapping)) {
      data.notes.push_back(dir.string() + " ran with another force mapping than " +
                           dirs.front().string() + ": its point is not on the curve drawn");
    }
    MappingPoint point;
    point.label = root.contains("scenario") && root.at("scenario").is_string()
                      ? root.at("scenario").get<std::string>()
                      : fs::path(dir).filename().string();
    if (point.label.empty()) point.label = dir.string();
    const Json& axial =
        root.contains("axial_resistance_N") ? root.at("axial_resistance_N") : Json();
    if (!axial.is_object()) {
      data.notes.push_back(dir.string() +
                           " never reached the constrained stage (no axial resistance): not "
                           "marked");
      continue;
    }
    point.scene_N = Number(axial, "mean", "axial_resistance_N.", file);
    point.device_N =
        Number(root.contains("delivered_force_N") ? root.at("delivered_force_N") : Json(), "mean",
               "delivered_force_N.", file);
    if (!(point.scene_N > 0.0)) {
      data.notes.push_back(dir.string() +
                           " has no positive axial resistance, which a log axis cannot show: not "
                           "marked");
      continue;
    }
    data.points.push_back(point);
  }
  return data;
}

void RenderMappingChart(const MappingChartData& data, const std::vector<OutputFile>& outputs) {
  if (outputs.empty()) throw std::invalid_argument("mapping chart: no output file");
  const TempDir work;
  RenderScript(Body(data), 1100, 650, outputs, work);
}

}  // namespace fitfeel::plot
