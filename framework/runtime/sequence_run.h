#pragma once

#include <filesystem>
#include <vector>

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

// Runs a sequence's steps in order (docs/assemblies.md), each as RunScene runs a scene, its
// outputs in DIR/<step>/ and the sequence's summary.json in DIR. Step k (from 0) draws with the
// seed plus k. Before a step runs, each feature it seats on an earlier step's part takes that
// step's final offset of its moving part (FeaturePlacement::seat). A step that fails or is
// interrupted removes the outputs of the steps before it: a sequence writes all or nothing.
FITFEEL_API SequenceResult RunSequence(const Sequence& sequence, const RunOptions& options);

}  // namespace fitfeel
