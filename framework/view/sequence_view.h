#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/export.h"
#include "framework/runtime/sequence_run.h"
#include "framework/scenario/sequence.h"
#include "framework/view/server.h"
#include "framework/view/tick_publisher.h"
#include "framework/view/view_model.h"

namespace fitfeel::view {

// The sequence message (JSON text) a client of a sequence's viewer receives first and again
// whenever it changes: `type` "sequence", `scenario`, `seed` (the sequence's; step k draws with
// it plus k), `newest` (the index, from 0, of the step the run is in, or of the last step once
// every step finished), and `steps`, one per step in order: `step` (its name), `seed`, `finished`
// and, once finished, its entry of the sequence's summary.json (StepSummary: `seated_offset_um`,
// `final_depth_mm`, `axial_resistance_N`, ...). `finished` holds the finished steps' entries in
// order.
FITFEEL_API std::string SequenceMessage(const Sequence& sequence, std::uint64_t seed,
                                        std::size_t newest,
                                        const std::vector<nlohmann::json>& finished);

// Shows a sequence's run on a viewer Server, each step as a scene. Before a step runs, its
// ViewModel is drawn from the scene the step runs (its seed and seats, StepScene) and it gets a
// TickPublisher of its own, so that the tick reports to the step's publisher as it reports to a
// scene's; the server shows the step from then on. After a step ran, the sequence message says
// what it left.
class FITFEEL_API SequenceView {
 public:
  // Draws step 0's parts (no seat moves them) and makes the server showing them; Start serving
  // with server().Start(). `seed`: the sequence's (RunOptions::seed or its run.seed). `sequence`
  // is borrowed and must outlive the view.
  SequenceView(const Sequence& sequence, std::uint64_t seed, const ServerOptions& options);
  ~SequenceView();
  SequenceView(const SequenceView&) = delete;
  SequenceView& operator=(const SequenceView&) = delete;

  Server& server() { return *server_; }
  // The watch to run the sequence with (RunSequence(sequence, options, view.Watch())), with the
  // seed given here: each step's model and publisher made and announced as it starts, what it
  // left announced as it ends. Called on the run's thread.
  SequenceWatch Watch();
  // The steps begun so far: step k's model and publisher (k below steps()).
  std::size_t steps() const { return models_.size(); }
  const ViewModel& model(std::size_t k) const { return *models_.at(k); }
  const TickPublisher& publisher(std::size_t k) const { return *publishers_.at(k); }

 private:
  const Sequence& sequence_;
  std::uint64_t seed_;
  std::vector<std::shared_ptr<const ViewModel>> models_;
  // Before the server: its steps borrow them, so they outlive it.
  std::vector<std::unique_ptr<TickPublisher>> publishers_;
  std::vector<nlohmann::json> finished_;
  std::unique_ptr<Server> server_;
};

}  // namespace fitfeel::view
