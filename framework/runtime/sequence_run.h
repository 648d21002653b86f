#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "framework/core/export.h"
#include "framework/runtime/run.h"
#include "framework/scenario/sequence.h"

namespace fitfeel {

struct SequenceResult {
  std::vector<RunResult> steps;  // in order
  std::filesystem::path summary;  // DIR/summary.json over the steps; empty when not written
  nlohmann::json summary_json;
};

// Watches a sequence's run between its steps, on the calling thread (a live viewer draws each
// step's parts before the step runs and shows what each finished step left).
struct SequenceWatch {
  // Before step k runs, with the scene it runs (its seed and seats set): returns the observer of
  // that step's run (null: none). Unset: every step reports to RunOptions::observer.
  std::function<TickObserver*(std::size_t k, const Scene& scene)> starting;
  // After step k ran, with its result and its entry of the sequence's summary (StepSummary).
  std::function<void(std::size_t k, const RunResult& result, const nlohmann::json& entry)>
      finished;
};

// The scene step k (from 0) of `sequence` runs: the step's own with the seed `seed` plus k and,
// for each feature the step seats on an earlier step's part, FeaturePlacement::seat set to
// `offsets[j]`, the offset at which step j's last tick left its moving part, along the axes the
// seat carries. `offsets` holds at least the earlier steps' offsets.
FITFEEL_API Scene StepScene(const Sequence& sequence, std::size_t k, std::uint64_t seed,
                            const std::vector<Eigen::Vector2d>& offsets);

// Step k's entry of the sequence's summary.json: its name, seed, folder, the offset where its part
// was left (`seated_offset_um`), its final depth, its axial and radial resistance and, for a
// several-feature step, its features' shares.
FITFEEL_API nlohmann::json StepSummary(const Sequence& sequence, std::size_t k,
                                       std::uint64_t seed, const RunResult& result);

// Runs a sequence's steps in order (docs/assemblies.md), each as RunScene runs a scene, its
// outputs in DIR/<step>/ and the sequence's summary.json in DIR. Step k runs StepScene: it draws
// with the seed plus k, and each feature it seats on an earlier step's part takes that step's
// final offset of its moving part (FeaturePlacement::seat). A step that fails or is interrupted
// removes the outputs of the steps before it: a sequence writes all or nothing.
FITFEEL_API SequenceResult RunSequence(const Sequence& sequence, const RunOptions& options,
                                       const SequenceWatch& watch = {});

}  // namespace fitfeel
