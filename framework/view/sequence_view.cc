#include "framework/view/sequence_view.h"

#include <utility>

namespace fitfeel::view {

std::string SequenceMessage(const Sequence& sequence, std::uint64_t seed, std::size_t newest,
                            const std::vector<nlohmann::json>& finished) {
  nlohmann::json steps = nlohmann::json::array();
  for (std::size_t k = 0; k < sequence.steps.size(); ++k) {
    nlohmann::json step = k < finished.size() ? finished[k] : nlohmann::json::object();
    step["step"] = sequence.steps[k].scene.name;
    step["seed"] = seed + k;
    step["finished"] = k < finished.size();
    steps.push_back(std::move(step));
  }
  return nlohmann::json{{"type", "sequence"},
                        {"scenario", sequence.name},
                        {"seed", seed},
                        {"newest", newest},
                        {"steps", std::move(steps)}}
      .dump();
}

SequenceView::SequenceView(const Sequence& sequence, std::uint64_t seed,
                           const ServerOptions& options)
    : sequence_(sequence), seed_(seed) {
  const Scene first = StepScene(sequence, 0, seed, {});
  models_.push_back(std::make_shared<const ViewModel>(first, first.run.seed, 0));
  publishers_.push_back(std::make_unique<TickPublisher>(1024, first.moving));
  std::vector<ServedStep> steps(1);
  steps[0].model = models_[0];
  steps[0].publisher = publishers_[0].get();
  server_ = std::make_unique<Server>(std::move(steps), SequenceMessage(sequence, seed, 0, {}),
                                     options);
}

SequenceView::~SequenceView() = default;

SequenceWatch SequenceView::Watch() {
  SequenceWatch watch;
  watch.starting = [this](std::size_t k, const Scene& scene) -> TickObserver* {
    // Step 0's parts are drawn already, before serving began.
    if (k > 0) {
      models_.push_back(
          std::make_shared<const ViewModel>(scene, scene.run.seed, static_cast<int>(k)));
      publishers_.push_back(std::make_unique<TickPublisher>(1024, scene.moving));
      ServedStep step;
      step.model = models_.back();
      step.publisher = publishers_.back().get();
      server_->BeginStep(std::move(step), SequenceMessage(sequence_, seed_, k, finished_));
    }
    return publishers_.at(k).get();
  };
  watch.finished = [this](std::size_t k, const RunResult&, const nlohmann::json& entry) {
    finished_.push_back(entry);
    server_->UpdateSequence(SequenceMessage(sequence_, seed_, k, finished_));
  };
  return watch;
}

}  // namespace fitfeel::view
