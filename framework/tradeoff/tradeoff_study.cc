#include "framework/tradeoff/tradeoff_study.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "framework/core/error.h"
#include "framework/plot/gnuplot.h"
#include "framework/runtime/run.h"
#include "framework/tradeoff/grid_ladder.h"

namespace fitfeel::tradeoff {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double Median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double Mean(const std::vector<double>& v) {
  return v.empty() ? kNaN
                   : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// Sample standard deviation (n - 1); 0 for a single value.
double SampleSd(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = Mean(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

// Mean |fy| over the constrained ticks of one run; NaN when none was constrained.
double MeanAxial(const RunSample& run) {
  double sum = 0.0;
  long n = 0;
  for (double f : run.fy) {
    if (std::isnan(f)) continue;
    sum += std::abs(f);
    ++n;
  }
  return n > 0 ? sum / static_cast<double>(n) : kNaN;
}

// Per tick, the mean over one grid's seeds; NaN where any seed's tick was not constrained.
std::vector<double> TraceMean(const std::vector<RunSample>& runs, std::size_t ticks) {
  std::vector<double> mean(ticks, kNaN);
  for (std::size_t t = 0; t < ticks; ++t) {
    double sum = 0.0;
    bool all = true;
    for (const RunSample& r : runs) {
      if (std::isnan(r.fy[t])) {
        all = false;
        break;
      }
      sum += r.fy[t];
    }
    if (all) mean[t] = sum / static_cast<double>(runs.size());
  }
  return mean;
}

// Variance of the mean over seeds of the paired differences a_s - b_s (sample variance / n; 0
// for one seed). Both grids run the same seeds, and grids that draw alike from a seed (same rows)
// differ far less than independent shapes would: pairing measures the sampling noise of the
// difference itself.
double PairedVarianceOfMean(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size();
  if (n < 2) return 0.0;
  double mean = 0.0;
  for (std::size_t s = 0; s < n; ++s) mean += a[s] - b[s];
  mean /= static_cast<double>(n);
  double ss = 0.0;
  for (std::size_t s = 0; s < n; ++s) ss += (a[s] - b[s] - mean) * (a[s] - b[s] - mean);
  return ss / static_cast<double>(n - 1) / static_cast<double>(n);
}

// A CSV cell of six significant digits; empty where the value is not finite.
std::string SixDigitCell(double value) {
  if (!std::isfinite(value)) return "";
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
  return std::string(buffer, result.ptr);
}

std::string ThreeDigits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

std::vector<double> ConstrainedFy(const std::string& trace_csv) {
  std::istringstream in(trace_csv);
  return ConstrainedFy(in);
}

std::vector<double> ConstrainedFy(std::istream& in) {
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("trace has no header");
  int stage_column = -1, fy_column = -1;
  {
    std::istringstream header(line);
    std::string name;
    for (int k = 0; std::getline(header, name, ','); ++k) {
      if (name == "stage") stage_column = k;
      if (name == "fy_N") fy_column = k;
    }
  }
  if (stage_column < 0 || fy_column < 0) {
    throw std::runtime_error("trace header lacks the stage or fy_N column");
  }
  std::vector<double> fy;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::string_view stage, value;
    std::size_t start = 0;
    for (int k = 0; start <= line.size(); ++k) {
      const std::size_t comma = std::min(line.find(',', start), line.size());
      const std::string_view cell(line.data() + start, comma - start);
      if (k == stage_column) stage = cell;
      if (k == fy_column) value = cell;
      start = comma + 1;
    }
    double f = 0.0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), f);
    if (ec != std::errc() || end != value.data() + value.size()) {
      throw std::runtime_error("trace has an unreadable fy_N value '" + std::string(value) + "'");
    }
    fy.push_back(stage == "constrained" ? f : kNaN);
  }
  return fy;
}

std::vector<GridRow> Summarize(const std::vector<std::string>& labels,
                               const std::vector<std::vector<RunSample>>& runs) {
  if (labels.size() != runs.size() || runs.empty()) {
    throw UserError("tradeoff: no grid to summarize");
  }
  const std::size_t seeds = runs.front().size();
  std::size_t ticks = std::numeric_limits<std::size_t>::max();
  for (const auto& grid : runs) {
    if (grid.empty() || grid.size() != seeds) {
      throw UserError("tradeoff: every grid needs the same number (>= 1) of runs");
    }
    for (const RunSample& r : grid) ticks = std::min(ticks, r.fy.size());
  }

  std::vector<GridRow> rows(runs.size());
  for (std::size_t g = 0; g < runs.size(); ++g) {
    GridRow& row = rows[g];
    const RunSample& first = runs[g].front();
    row.label = labels[g];
    row.inner_rows = first.inner_rows;
    row.inner_columns = first.inner_columns;
    row.outer_rows = first.outer_rows;
    row.outer_columns = first.outer_columns;
    row.inner_cells = static_cast<long>(first.inner_rows) * first.inner_columns;
    row.outer_cells = static_cast<long>(first.outer_rows) * first.outer_columns;
    row.seeds = static_cast<int>(seeds);
    std::vector<double> prepare, p50, p99, means;
    for (const RunSample& r : runs[g]) {
      prepare.push_back(r.prepare_seconds);
      p50.push_back(r.tick_p50_us);
      p99.push_back(r.tick_p99_us);
      const double m = MeanAxial(r);
      if (std::isnan(m)) {
        throw UserError("tradeoff: a run at grid " + row.label +
                        " never reached the constrained stage: no axial resistance to compare "
                        "(is the duration long enough for the parts to meet?)");
      }
      means.push_back(m);
    }
    row.prepare_seconds = Median(prepare);
    row.tick_p50_us = Median(p50);
    row.tick_p99_us = Median(p99);
    row.run_means_N = means;
    row.mean_axial_N = Mean(means);
    row.sd_axial_N = SampleSd(means);
    row.se_axial_N = row.sd_axial_N / std::sqrt(static_cast<double>(seeds));
  }

  // Coarse to fine; the finest (most cells over both parts) is the reference.
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return rows[a].inner_cells + rows[a].outer_cells < rows[b].inner_cells + rows[b].outer_cells;
  });
  const std::size_t ref = order.back();
  const std::vector<double> ref_mean = TraceMean(runs[ref], ticks);
  const double scale = rows[ref].mean_axial_N;

  std::vector<GridRow> sorted;
  for (std::size_t g : order) {
    GridRow row = rows[g];
    row.reference = g == ref;
    row.bias_N = row.mean_axial_N - scale;
    row.bias_se_N = std::sqrt(PairedVarianceOfMean(row.run_means_N, rows[ref].run_means_N));
    const std::vector<double> mean = TraceMean(runs[g], ticks);
    std::vector<double> a(seeds), b(seeds);
    double ss = 0.0, noise = 0.0, worst = 0.0;
    long n = 0;
    for (std::size_t t = 0; t < ticks; ++t) {
      if (std::isnan(mean[t]) || std::isnan(ref_mean[t])) continue;
      const double d = std::abs(mean[t] - ref_mean[t]);
      ss += d * d;
      worst = std::max(worst, d);
      for (std::size_t k = 0; k < seeds; ++k) {
        a[k] = runs[g][k].fy[t];
        b[k] = runs[ref][k].fy[t];
      }
      noise += PairedVarianceOfMean(a, b);
      ++n;
    }
    if (n == 0) {
      throw UserError("tradeoff: no tick is constrained in every run of grid " + row.label +
                      " and of the reference " + rows[ref].label + ": nothing to compare");
    }
    row.compared_ticks = n;
    row.rms_error_N = std::sqrt(ss / static_cast<double>(n));
    row.max_error_N = worst;
    row.noise_rms_N = std::sqrt(noise / static_cast<double>(n));
    row.rms_error_rel = scale > 0.0 ? row.rms_error_N / scale : kNaN;
    row.max_error_rel = scale > 0.0 ? row.max_error_N / scale : kNaN;
    sorted.push_back(row);
  }
  return sorted;
}

void AdmitLadder(const Scene& scene, const TradeoffSettings& settings) {
  if (settings.seeds < 1) throw UserError("tradeoff: --seeds must be at least 1");
  Scene probe = scene;
  if (settings.duration) probe.run.duration = *settings.duration;
  probe.run.write_trace = true;  // each run's trace is written, then read back
  probe.run.write_summary = false;
  probe.run.write_recording = false;
  double ticks = 0.0;
  for (const Resolution& grid : settings.ladder) {
    probe.model.resolution = grid;
    SceneCost cost;
    try {
      cost = EstimateSceneCost(probe);
    } catch (const UserError& e) {
      throw UserError("tradeoff: --resolutions: expected a grid the surface type can discretize, "
                      "found " + Label(grid) + ": " + e.what());
    }
    ticks = cost.trace_rows;
    if (settings.allow_large) continue;
    if (const std::optional<CostRefusal> refusal = LargeCostRefusal(cost)) {
      throw UserError(
          std::string("tradeoff: ") + (refusal->output ? "--duration" : "--resolutions") +
          ": expected " + refusal->expected + ", found " +
          (refusal->output ? ThreeDigits(probe.run.duration) + " s" : Label(grid)) + ": " +
          refusal->found);
    }
  }
  // The comparison holds every run's axial trace (a double per tick) until it summarizes.
  const double held = static_cast<double>(settings.ladder.size()) * settings.seeds * ticks *
                      static_cast<double>(sizeof(double));
  if (!settings.allow_large && held > kLargeSceneBytes) {
    throw UserError("tradeoff: --seeds: expected a study whose axial traces (8 B a tick of every "
                    "run) are held within " + ThreeDigits(kLargeSceneBytes / (1 << 30)) +
                    " GiB, or --allow-large to run it anyway, found " +
                    std::to_string(settings.ladder.size()) +
                    (settings.ladder.size() == 1 ? " grid x " : " grids x ") +
                    std::to_string(settings.seeds) + " seeds x " + ThreeDigits(ticks) +
                    " ticks: " + ThreeDigits(held / (1 << 30)) + " GiB");
  }
}

std::vector<Resolution> AdmittedGrids(const Scene& scene, const std::vector<Resolution>& ladder,
                                      bool allow_large, std::vector<std::string>* left_out) {
  Scene probe = scene;
  std::vector<Resolution> admitted;
  for (const Resolution& grid : ladder) {
    probe.model.resolution = grid;
    SceneCost cost;
    try {
      cost = EstimateSceneCost(probe);
    } catch (const UserError& e) {
      left_out->push_back(Label(grid) + ", which the surface type cannot discretize (" +
                          e.what() + ")");
      continue;
    }
    cost.output_bytes = 0.0;  // the same for every grid: AdmitLadder's
    const std::optional<CostRefusal> refusal = LargeCostRefusal(cost);
    if (refusal && !allow_large) {
      left_out->push_back(Label(grid) + ", over the large-scene thresholds (" + refusal->found +
                          "; --allow-large keeps it)");
      continue;
    }
    admitted.push_back(grid);
  }
  return admitted;
}

std::vector<GridRow> RunTradeoff(const std::function<Scene()>& load,
                                 const TradeoffSettings& settings) {
  if (settings.ladder.empty()) throw UserError("tradeoff: no grid to run");
  if (settings.seeds < 1) throw UserError("tradeoff: --seeds must be at least 1");
  if (settings.duration && !(*settings.duration > 0.0 && std::isfinite(*settings.duration))) {
    throw UserError("tradeoff: --duration must be a positive time");
  }
  AdmitLadder(load(), settings);

  std::vector<std::string> labels;
  std::vector<std::vector<RunSample>> runs;
  for (const Resolution& grid : settings.ladder) {
    std::vector<RunSample> samples;
    std::uint64_t first_seed = 0;
    for (int s = 0; s < settings.seeds; ++s) {
      Scene scene = load();
      if (s == 0) first_seed = scene.run.seed;
      scene.model.resolution = grid;
      if (settings.duration) scene.run.duration = *settings.duration;
      scene.run.write_trace = true;
      scene.run.write_summary = false;
      scene.run.write_recording = false;
      const plot::TempDir folder;
      RunOptions options;
      options.out_dir = folder.path();
      options.clock = ClockMode::kVirtual;
      options.seed = first_seed + static_cast<std::uint64_t>(s);
      const RunResult result = RunScene(std::move(scene), options);
      RunSample sample;
      sample.inner_rows = result.info.inner_rows;
      sample.inner_columns = result.info.inner_columns;
      sample.outer_rows = result.info.outer_rows;
      sample.outer_columns = result.info.outer_columns;
      sample.prepare_seconds = result.info.prepare_seconds;
      sample.tick_p50_us = result.stats.compute_us.p50;
      sample.tick_p99_us = result.stats.compute_us.p99;
      std::ifstream trace(result.paths.trace, std::ios::binary);
      if (!trace) throw std::runtime_error("cannot read '" + result.paths.trace.string() + "'");
      sample.fy = ConstrainedFy(trace);
      samples.push_back(std::move(sample));
    }
    std::string label = Label(grid);
    const RunSample& got = samples.front();
    if (grid.is_auto()) {
      const std::string inner =
          std::to_string(got.inner_rows) + "x" + std::to_string(got.inner_columns);
      const std::string outer =
          std::to_string(got.outer_rows) + "x" + std::to_string(got.outer_columns);
      label = "auto = " + inner + (inner == outer ? "" : "/" + outer);
    }
    // One grid run twice (auto resolving to a ladder grid): keep the first runs, both names.
    bool merged = false;
    for (std::size_t g = 0; g < runs.size(); ++g) {
      const RunSample& other = runs[g].front();
      if (other.inner_rows == got.inner_rows && other.inner_columns == got.inner_columns &&
          other.outer_rows == got.outer_rows && other.outer_columns == got.outer_columns) {
        labels[g] += " (" + label + ")";
        merged = true;
      }
    }
    if (settings.progress) {
      settings.progress("grid " + label + ": " + std::to_string(settings.seeds) + " runs" +
                        (merged ? ", same grid as an earlier one" : ""));
    }
    if (merged) continue;
    labels.push_back(label);
    runs.push_back(std::move(samples));
  }
  return Summarize(labels, runs);
}

std::string TradeoffCsv(const std::vector<GridRow>& rows) {
  std::string text =
      "grid,inner_rows,inner_columns,outer_rows,outer_columns,inner_cells,outer_cells,seeds,"
      "prepare_s,tick_p50_us,tick_p99_us,mean_axial_N,sd_axial_N,se_axial_N,bias_N,bias_se_N,"
      "rms_error_N,max_error_N,rms_error_rel,max_error_rel,noise_rms_N,compared_ticks,"
      "reference\n";
  for (const GridRow& r : rows) {
    std::string label = r.label;
    if (label.find(',') != std::string::npos) label = "\"" + label + "\"";
    text += label + "," + std::to_string(r.inner_rows) + "," + std::to_string(r.inner_columns) +
            "," + std::to_string(r.outer_rows) + "," + std::to_string(r.outer_columns) + "," +
            std::to_string(r.inner_cells) + "," + std::to_string(r.outer_cells) + "," +
            std::to_string(r.seeds) + "," + SixDigitCell(r.prepare_seconds) + "," +
            SixDigitCell(r.tick_p50_us) + "," + SixDigitCell(r.tick_p99_us) + "," +
            SixDigitCell(r.mean_axial_N) + "," + SixDigitCell(r.sd_axial_N) + "," +
            SixDigitCell(r.se_axial_N) + "," + SixDigitCell(r.bias_N) + "," +
            SixDigitCell(r.bias_se_N) + "," + SixDigitCell(r.rms_error_N) + "," +
            SixDigitCell(r.max_error_N) + "," + SixDigitCell(r.rms_error_rel) + "," +
            SixDigitCell(r.max_error_rel) + "," + SixDigitCell(r.noise_rms_N) + "," +
            std::to_string(r.compared_ticks) + "," + (r.reference ? "yes" : "no") + "\n";
  }
  return text;
}

}  // namespace fitfeel::tradeoff
