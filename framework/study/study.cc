#include "framework/study/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include "framework/core/atomic_files.h"
#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/core/parallel.h"
#include "framework/model/shared_prepare.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/runtime/scene_stages.h"
#include "framework/scenario/scene.h"
#include "framework/scenario/yaml_file.h"
#include "framework/study/pair_geometry.h"

namespace fitfeel::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// Shortest decimal that reads back to the same double (CSV and JSON both).
double Stat(const nlohmann::json& summary, const char* key, const char* field) {
  const auto it = summary.find(key);
  if (it == summary.end() || it->is_null()) return 0.0;
  return it->at(field).get<double>();
}

// The loader's options of a study: no trace or recording is written (only the summary's
// statistics), so their size is not admitted.
LoadOptions StudyLoad(bool allow_large) {
  LoadOptions load;
  load.allow_large = allow_large;
  load.writes_outputs = false;
  return load;
}

PairResult RunPair(const fs::path& file, const PluginRegistry& registry, int index,
                   std::uint64_t study_seed, const LoadOptions& load, SharedPrepare* shared) {
  PairResult pair;
  pair.pair = index;
  pair.seed = PairSeed(study_seed, index);
  // A scene of its own per pair: its own device and plugin objects. Pairs share only the
  // registry's read-only tables and what the prepare computes from the scene alone (`shared`:
  // read-only once made, the same bits as a pair's own solve would give).
  Scene scene = LoadScene(file, registry, load);
  const bool checked =
      scene.inner.material.yield_strength > 0.0 || scene.outer.material.yield_strength > 0.0;
  scene.run.write_trace = false;
  scene.run.write_summary = false;
  scene.run.write_recording = false;
  RunOptions options;
  options.seed = pair.seed;
  options.clock = ClockMode::kVirtual;
  options.shared = shared;
  options.prepared = [&pair](const PreparedScene& prepared) {
    const PairGeometry geometry = MeasurePair(*prepared.inner_sms, *prepared.outer_sms);
    pair.shaft_size_um = geometry.inner_size * 1e6;
    pair.hole_size_um = geometry.outer_size * 1e6;
    if (geometry.min_clearance) pair.min_clearance_um = *geometry.min_clearance * 1e6;
    pair.rejections = prepared.inner_sms->rejections + prepared.outer_sms->rejections;
  };
  const auto start = Clock::now();
  const RunResult run = RunScene(std::move(scene), options);
  pair.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  const nlohmann::json& s = run.summary;
  pair.interfering = s.value("interference_ticks", 0) > 0;
  pair.constrained_ticks = s.value("constrained_ticks", 0);
  pair.axial_mean_N = Stat(s, "axial_resistance_N", "mean");
  pair.axial_max_N = Stat(s, "axial_resistance_N", "max");
  pair.radial_max_N = Stat(s, "radial_resistance_N", "max");
  if (const auto elastic = s.find("elastic_limit"); elastic != s.end()) {
    const auto u = elastic->find("max_utilisation");
    if (u != elastic->end() && !u->is_null()) {
      pair.elastic_utilisation_max = u->get<double>();
    } else if (checked) {
      pair.elastic_utilisation_max = 0.0;  // checked, but no tick ever pressed the parts
    }
    pair.plastic = elastic->value("yielding_ticks", 0) > 0;
  }
  pair.prepare_s = run.info.prepare_seconds;
  return pair;
}

nlohmann::json DistributionJson(const Distribution& d) {
  return {{"p5", d.p5},   {"p25", d.p25}, {"p50", d.p50},
          {"p75", d.p75}, {"p95", d.p95}, {"mean", d.mean}};
}

}  // namespace

PairResult RunStudyPair(const fs::path& file, const PluginRegistry& registry, std::uint64_t seed,
                        int index) {
  if (index < 0) throw UserError("study: pair index must be >= 0, got " + std::to_string(index));
  // A worker process runs pair after pair of the same study: what their prepares share is kept
  // for the process's life. Its keys spell out every input, so pairs of other scenes, or a
  // scenario edited between calls, never take a value that is not theirs. Never destroyed: its
  // values were made by plugin code, which a registry may have unloaded before static
  // destructors run.
  static SharedPrepare* const shared = new SharedPrepare();
  return RunPair(file, registry, index, seed, StudyLoad(false), shared);
}

std::uint64_t PairSeed(std::uint64_t seed, int index) {
  return SplitMix64(SplitMix64(seed) ^ static_cast<std::uint64_t>(index));
}

Distribution Describe(std::vector<double> values) {
  Distribution d;
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  auto at = [&values](double p) {
    const double h = (static_cast<double>(values.size()) - 1.0) * p / 100.0;
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
  };
  d.p5 = at(5.0);
  d.p25 = at(25.0);
  d.p50 = at(50.0);
  d.p75 = at(75.0);
  d.p95 = at(95.0);
  double sum = 0.0;
  for (double v : values) sum += v;
  d.mean = sum / static_cast<double>(values.size());
  return d;
}

StudyResult RunStudy(const fs::path& file, const PluginRegistry& registry,
                     const StudySettings& settings) {
  if (settings.pairs < 1 || settings.pairs > 10'000'000) {
    throw UserError("study: --pairs must be in 1..10000000, got " + std::to_string(settings.pairs));
  }
  if (settings.threads < 1 || settings.threads > 1024) {
    throw UserError("study: --threads must be in 1..1024, got " + std::to_string(settings.threads));
  }
  // Every refusal of the scene comes now, before any pair runs (and from this thread).
  const Scene checked = LoadScene(file, registry, StudyLoad(settings.allow_large));
  if (!checked.device) {
    throw UserError("study: scene '" + checked.name + "' has no device '" + checked.device_id +
                    "'");
  }
  // A pair's columns are a cylinder's (sizes, clearance, axial resistance): for a nut on a bolt
  // they would read the pitch diameters as a shaft and a hole and the run-down push as the fit.
  if (IsScrewScene(checked)) {
    scenario::LoadYamlFile(file).Child("surface").Fail(
        "a surface whose pairs a fit study compares (a screw joint's preload and torque are no "
        "study columns yet: run it seed by seed with `fitfeel run FILE --seed S`, summary.json's "
        "`thread`)",
        checked.surface_id + ", a screw joint");
  }

  StudyResult result;
  result.scenario = checked.name;
  result.scenario_file = file;
  result.requested_pairs = settings.pairs;
  result.seed = settings.seed;
  result.threads = std::min(settings.threads, settings.pairs);

  std::vector<std::optional<PairResult>> slots(static_cast<std::size_t>(settings.pairs));
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::mutex report_mutex;  // progress callback and the first failure; never per tick
  std::exception_ptr failure;
  int done = 0;
  // What the pairs' prepares compute from the scene alone, made by the first pair that needs it.
  SharedPrepare shared;
  const auto start = Clock::now();
  auto worker = [&] {
    // Pairs on every thread already keep the cores busy: each pair prepares on its own thread
    // instead of spreading over all of them (the result does not depend on it).
    std::optional<ScopedPrepareThreads> one_thread;
    if (result.threads > 1) one_thread.emplace(1);
    while (!failed.load()) {
      if (settings.stop != nullptr && settings.stop->load()) return;
      const int i = next.fetch_add(1);
      if (i >= settings.pairs) return;
      try {
        slots[static_cast<std::size_t>(i)] =
            RunPair(file, registry, i, settings.seed, StudyLoad(settings.allow_large),
                    settings.share_prepare ? &shared : nullptr);
      } catch (...) {
        std::lock_guard<std::mutex> lock(report_mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
        return;
      }
      std::lock_guard<std::mutex> lock(report_mutex);
      ++done;
      if (settings.progress) settings.progress(done, settings.pairs);
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < result.threads; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  result.wall_s = std::chrono::duration<double>(Clock::now() - start).count();

  // Workers take pairs in index order and finish what they took, so the pairs done are a prefix.
  for (auto& slot : slots) {
    if (!slot) break;
    result.pairs.push_back(*slot);
  }
  result.interrupted = static_cast<int>(result.pairs.size()) < settings.pairs;
  return result;
}

std::string PairsCsv(const StudyResult& result) {
  std::string text =
      "pair,seed,shaft_size_um,hole_size_um,min_clearance_um,interfering,axial_mean_N,"
      "axial_max_N,radial_max_N,constrained_ticks,plastic,elastic_utilisation_max,rejections\n";
  for (const PairResult& p : result.pairs) {
    text +=
        std::to_string(p.pair) + ',' + std::to_string(p.seed) + ',' +
        ShortestDecimal(p.shaft_size_um) + ',' + ShortestDecimal(p.hole_size_um) + ',' +
        (p.min_clearance_um ? ShortestDecimal(*p.min_clearance_um) : std::string()) + ',' +
        (p.interfering ? "1" : "0") + ',' + ShortestDecimal(p.axial_mean_N) + ',' +
        ShortestDecimal(p.axial_max_N) + ',' + ShortestDecimal(p.radial_max_N) + ',' +
        std::to_string(p.constrained_ticks) + ',' +
        (p.elastic_utilisation_max ? (p.plastic ? "1" : "0") : "") + ',' +
        (p.elastic_utilisation_max ? ShortestDecimal(*p.elastic_utilisation_max) : std::string()) +
        ',' + std::to_string(p.rejections) + '\n';
  }
  return text;
}

std::string StudyJson(const StudyResult& result) {
  std::vector<double> mean, max;
  int interfering = 0;
  int checked = 0;
  int plastic = 0;
  long rejections = 0;
  for (const PairResult& p : result.pairs) {
    if (p.elastic_utilisation_max) ++checked;
    if (p.elastic_utilisation_max && p.plastic) ++plastic;
    mean.push_back(p.axial_mean_N);
    max.push_back(p.axial_max_N);
    if (p.interfering) ++interfering;
    rejections += p.rejections;
  }
  const double n = static_cast<double>(result.pairs.size());
  nlohmann::json j;
  j["scenario"] = result.scenario;
  j["scenario_file"] = result.scenario_file.string();
  j["pairs"] = result.pairs.size();
  j["requested_pairs"] = result.requested_pairs;
  j["interrupted"] = result.interrupted;
  j["seed"] = result.seed;
  j["threads"] = result.threads;
  j["probability_of_interference"] = n > 0 ? interfering / n : 0.0;
  // Among the pairs whose stresses were checked against a yield strength; null when none was.
  j["probability_of_yield"] =
      checked > 0 ? nlohmann::json(static_cast<double>(plastic) / checked) : nlohmann::json();
  j["axial_mean_N"] = DistributionJson(Describe(mean));
  j["axial_max_N"] = DistributionJson(Describe(max));
  // Scrapped parts over all parts made (two kept per pair).
  const double made = 2.0 * n + static_cast<double>(rejections);
  j["scrap_rate"] = made > 0 ? static_cast<double>(rejections) / made : 0.0;
  // Timings vary from run to run: they are here, never in pairs.csv (which is byte-identical for
  // a scene, seed and N).
  std::vector<double> prepare;
  for (const PairResult& p : result.pairs) prepare.push_back(p.prepare_s);
  j["prepare_s_median"] = Describe(prepare).p50;
  j["wall_s"] = result.wall_s;
  j["pairs_per_s"] = result.wall_s > 0 ? n / result.wall_s : 0.0;
  return j.dump(2) + "\n";
}

void WriteStudy(const fs::path& dir, const StudyResult& result) {
  WriteFilesAtomically(dir, {{"pairs.csv", PairsCsv(result)}, {"study.json", StudyJson(result)}});
}

}  // namespace fitfeel::study
