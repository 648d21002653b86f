#include "framework/runtime/sequence_run.h"

#include <string>
#include <system_error>

#include "framework/core/atomic_files.h"
#include "framework/core/error.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// Removes what a finished step wrote, and its folder when nothing else is left in it.
void RemoveOutputs(const RunResult& result) {
  std::error_code ignored;
  fs::path folder;
  for (const fs::path& path :
       {result.paths.trace, result.paths.summary, result.paths.recording}) {
    if (path.empty()) continue;
    folder = path.parent_path();
    fs::remove(path, ignored);
  }
  if (!folder.empty() && fs::is_empty(folder, ignored)) fs::remove(folder, ignored);
}

}  // namespace

Scene StepScene(const Sequence& sequence, std::size_t k, std::uint64_t seed,
                const std::vector<Eigen::Vector2d>& offsets) {
  const SequenceStep& step = sequence.steps.at(k);
  Scene scene = step.scene;
  scene.run.seed = seed + k;
  for (const SequenceStep::Seat& seat : step.seated) {
    Eigen::Vector2d& place = scene.features.at(seat.feature).placement.seat;
    place = offsets.at(seat.step);
    if (!seat.x) place.x() = 0.0;
    if (!seat.z) place.y() = 0.0;
  }
  return scene;
}

nlohmann::json StepSummary(const Sequence& sequence, std::size_t k, std::uint64_t seed,
                           const RunResult& r) {
  nlohmann::json s;
  s["step"] = sequence.steps.at(k).scene.name;
  s["seed"] = seed + k;
  s["folder"] = sequence.steps[k].scene.name;
  // Where the step left its part for a later step to sit on: nowhere (zero offset) when it
  // ended in free motion.
  const bool seated = r.final_stage == StageId::kConstrained;
  s["seated"] = seated;
  s["seated_offset_um"] = {seated ? r.final_pose.offset.x() * 1e6 : 0.0,
                           seated ? r.final_pose.offset.y() * 1e6 : 0.0};
  s["final_depth_mm"] = r.final_pose.depth * 1e3;
  s["axial_resistance_N"] = r.summary.value("axial_resistance_N", nlohmann::json());
  s["radial_resistance_N"] = r.summary.value("radial_resistance_N", nlohmann::json());
  if (r.summary.contains("features")) s["features"] = r.summary["features"];
  return s;
}

SequenceResult RunSequence(const Sequence& sequence, const RunOptions& options,
                           const SequenceWatch& watch) {
  if (sequence.steps.empty()) throw UserError("sequence '" + sequence.name + "' has no step");
  SequenceResult result;
  const std::uint64_t seed = options.seed ? *options.seed : sequence.run.seed;
  nlohmann::json steps = nlohmann::json::array();
  try {
    std::vector<Eigen::Vector2d> offsets;
    for (std::size_t k = 0; k < sequence.steps.size(); ++k) {
      const SequenceStep& step = sequence.steps[k];
      // A part whose step ended before it mated (a duration too short for the device to bring
      // it in) was never seated: the later step takes that feature's side at its drawn place,
      // and says so. The run goes on: whether a step seats its part is the run's outcome, not
      // the scene's, and `validate` cannot refuse it.
      std::vector<std::string> notes;
      for (const SequenceStep::Seat& seat : step.seated) {
        if (result.steps.at(seat.step).final_stage != StageId::kConstrained) {
          notes.push_back("note: step '" + sequence.steps[seat.step].scene.name +
                          "' ended with its part in free motion, never seated: step '" +
                          step.scene.name + "' takes its feature '" +
                          step.scene.features.at(seat.feature).name +
                          "' at its drawn place (a longer duration seats it)");
        }
      }
      Scene scene = StepScene(sequence, k, seed, offsets);
      RunOptions step_options = options;
      step_options.seed.reset();
      if (!options.out_dir.empty()) step_options.out_dir = options.out_dir / scene.name;
      if (watch.starting) step_options.observer = watch.starting(k, scene);
      result.steps.push_back(RunScene(std::move(scene), step_options));
      RunResult& done = result.steps.back();
      done.notes.insert(done.notes.end(), notes.begin(), notes.end());
      offsets.push_back(done.final_stage == StageId::kConstrained ? done.final_pose.offset
                                                                  : Eigen::Vector2d::Zero());
      steps.push_back(StepSummary(sequence, k, seed, result.steps.back()));
      if (watch.finished) watch.finished(k, result.steps.back(), steps.back());
    }
  } catch (...) {
    for (const RunResult& done : result.steps) RemoveOutputs(done);
    throw;
  }
  nlohmann::json j;
  j["scenario"] = sequence.name;
  j["scenario_file"] = sequence.file.string();
  j["seed"] = seed;
  j["steps"] = steps;
  result.summary_json = j;
  if (!options.out_dir.empty() && sequence.run.write_summary) {
    try {
      WriteFilesAtomically(options.out_dir, {{"summary.json", j.dump(2) + "\n"}});
    } catch (...) {
      for (const RunResult& done : result.steps) RemoveOutputs(done);
      throw;
    }
    result.summary = options.out_dir / "summary.json";
  }
  return result;
}

}  // namespace fitfeel
