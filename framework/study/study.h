#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/export.h"

namespace fitfeel {

class PluginRegistry;

namespace study {

// A fit study (README.md): N part pairs drawn from one scenario, each inserted in virtual time,
// summarised as a population. Pair i runs with the seed PairSeed(seed, i), so a pair's result
// depends only on the scenario, the study seed and i: not on the number of threads, nor on the
// order in which the pairs finish.

struct StudySettings {
  int pairs = 100;
  std::uint64_t seed = 1;
  int threads = 1;
  // Run a scene whose estimated preparation exceeds the large-scene thresholds (LoadOptions).
  bool allow_large = false;
  // Polled before each pair starts; when it becomes true no new pair starts and the pairs under
  // way finish, so the result holds the pairs 0 .. k-1 for some k (a valid, smaller study).
  const std::atomic<bool>* stop = nullptr;
  // Pairs share what their prepares compute from the scene alone (SharedPrepare: the elastic
  // model's elements); off, every pair computes everything itself. The pairs are the same bit for
  // bit either way: off is for comparing the two.
  bool share_prepare = true;
  // Called (from the worker threads, serialised) after each finished pair with the count done.
  std::function<void(int done, int total)> progress;
};

// What one pair's insertion left. Sizes are diametral deviations from the nominal size, um.
struct PairResult {
  int pair = 0;
  std::uint64_t seed = 0;
  double shaft_size_um = 0.0;  // actual size of the inner part (mean of its per-cell size draw)
  double hole_size_um = 0.0;   // actual size of the outer part
  // Smallest diametral clearance the pair passes through during a rigid insertion that may take
  // any offset but no tilt (see README.md); negative: the parts must deform to pass. Absent for a
  // surface type that is not a circular cylinder.
  std::optional<double> min_clearance_um;
  bool interfering = false;   // any constrained tick of the run was in interference
  double axial_mean_N = 0.0;  // over the constrained ticks (summary.json's axial_resistance_N)
  double axial_max_N = 0.0;
  double radial_max_N = 0.0;
  int constrained_ticks = 0;
  // Largest equivalent stress over the yield strength over the run (summary.json's
  // elastic_limit), 0 when no tick pressed the parts; absent when neither part has a yield
  // strength.
  std::optional<double> elastic_utilisation_max;
  bool plastic = false;  // some tick yielded (utilisation > 1): the elastic model no longer holds
  int rejections = 0;    // parts a statistical process scrapped before this pair's two parts
  double prepare_s = 0.0;
  double wall_s = 0.0;
};

struct Distribution {
  double p5 = 0.0, p25 = 0.0, p50 = 0.0, p75 = 0.0, p95 = 0.0, mean = 0.0;
};

struct StudyResult {
  std::string scenario;
  std::filesystem::path scenario_file;
  int requested_pairs = 0;
  std::uint64_t seed = 0;
  int threads = 1;
  bool interrupted = false;       // stopped before every pair ran
  std::vector<PairResult> pairs;  // in pair order, 0 .. pairs.size() - 1
  double wall_s = 0.0;
};

// The seed of pair `index` of a study seeded with `seed` (SplitMix64 of both: neighbouring study
// seeds give unrelated pairs).
FITFEEL_API std::uint64_t PairSeed(std::uint64_t seed, int index);

// Percentile p (0..100) of `values` by linear interpolation between order statistics (the
// definition R and NumPy call type 7); the values are copied. Zeros for an empty vector.
FITFEEL_API Distribution Describe(std::vector<double> values);

// Pair `index` of a study seeded `seed` of the scenario `file`, alone: what RunStudy computes for
// it (a distributed study runs pairs where it likes and gathers them). Throws UserError.
FITFEEL_API PairResult RunStudyPair(const std::filesystem::path& file,
                                    const PluginRegistry& registry, std::uint64_t seed, int index);

// Runs the study of the scenario `file`. Throws UserError (ScenarioError) before any pair runs
// when the scenario, the settings or the plugins are unusable.
FITFEEL_API StudyResult RunStudy(const std::filesystem::path& file, const PluginRegistry& registry,
                                 const StudySettings& settings);

// The files of a study, as text.
FITFEEL_API std::string PairsCsv(const StudyResult& result);
FITFEEL_API std::string StudyJson(const StudyResult& result);

// Writes DIR/pairs.csv and DIR/study.json, both or neither (temporary names, then renames).
FITFEEL_API void WriteStudy(const std::filesystem::path& dir, const StudyResult& result);

}  // namespace study
}  // namespace fitfeel
