#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/export.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/view/server.h"
#include "framework/view/tick_publisher.h"

namespace fitfeel::view {

struct LiveSessionOptions {
  ServerOptions server;
  LoadOptions load;
  std::optional<std::uint64_t> seed;  // overrides the scenarios' run.seed
  // The run's clock: real time (a person at the device) unless a test asks for virtual time.
  ClockMode clock = ClockMode::kRealTime;
  // Borrowed, may be null: once set, the pass running ends at its next tick and Run returns (an
  // interrupt, or the command's --exit-after).
  const std::atomic<bool>* stop = nullptr;
  // Where the session says what it did (a line each); empty: nowhere.
  std::function<void(const std::string&)> say;
};

// A live view that the page can change while the device keeps running: the scene runs in passes,
// each a whole run of its device's script (RunPreparedScene, the device started again, so a
// robot's part starts withdrawn), one after another until stopped. A pass renders one prepared
// scene; a new scene (an edit, the other scene of a comparison) is prepared off the tick on the
// session's own thread and swapped in at a tick where the moving part is out of contact (the
// pass ends there and the next renders the new scene), or at once when asked ("now": the pass
// ends at the next tick and the next starts from the device's start, the part withdrawn). The
// tick never waits for a preparation and never sees a half-made scene.
//
// Two kinds:
//  - edits: the page changes a one-feature scenario's sizes (ISO 286 classes, fits), form and
//    texture values, friction and seed (scene_edits.h). Each edit is loaded as `fitfeel validate`
//    loads a file; one it refuses is shown in the page with the loader's located message and
//    leaves the running scene untouched.
//  - comparison: two scenarios prepared side by side; the page selects which one the device
//    renders (a key or a button), and draws both scenes' traces.
//
// Messages from the page (JSON text): {"type":"edit","edits":{path: value...},"apply":"check" |
// "free" | "now"}, {"type":"apply","now":true} (the edit waiting for a free part, at once),
// {"type":"select","scene":0|1,"now":bool}. The panel message (JSON, `type` "live") says what
// can be edited, what the last edit gave, which scene renders, and how many passes ran.
class FITFEEL_API LiveSession {
 public:
  // Messages waiting for the session's thread at most; more are dropped.
  static constexpr std::size_t kMaxWaitingMessages = 64;

  // Loads `file` (a one-feature or several-feature scene; not a sequence) for edits, or `file`
  // and `compare` for a comparison, prepares them and makes the server (not yet serving). Throws
  // ScenarioError/UserError as `fitfeel view` does for a scene that cannot run.
  LiveSession(const std::filesystem::path& file,
              const std::optional<std::filesystem::path>& compare, const PluginRegistry& registry,
              LiveSessionOptions options);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  Server& server() { return *server_; }
  // Runs passes until options.stop is set (or `passes` passes ran, when given: tests). The
  // calling thread is the tick's.
  void Run(std::optional<std::uint64_t> passes = std::nullopt);
  // A message as the page sends it (the server's on_message calls this). Any thread; returns at
  // once, the work is done on the session's thread.
  void Submit(const std::string& message);
  // Waits until the session's thread has handled every message submitted so far (tests).
  void Drain();
  // Ends the running pass at its next tick and Run after it (any thread).
  void Stop() { stop_.store(true); }
  // The newest panel message (any thread).
  nlohmann::json panel() const;
  // Passes ended so far, and scenes swapped in (any thread).
  std::uint64_t passes() const { return passes_.load(); }
  std::uint64_t swaps() const { return swaps_.load(); }
  // The largest axial resistance of the constrained stage in the last pass that ended, N (any
  // thread).
  double last_pass_peak() const { return last_pass_peak_.load(); }
  // The name of the scene the next pass renders (any thread).
  std::string rendering() const;

 private:
  struct Slot;
  class PassObserver;

  // A scenario file's slot, with options.seed applied to its scene and its text.
  std::shared_ptr<Slot> OpenSlot(const std::filesystem::path& file, const std::string& label) const;
  // `loaded`, the scene of `yaml` (named `file`), prepared with its view model.
  std::shared_ptr<Slot> MakeSlot(std::string yaml, Scene loaded, const std::filesystem::path& file,
                                 const std::string& label) const;
  void Work();
  void Handle(const std::string& message);
  void HandleEdit(const nlohmann::json& message);
  void Offer(std::shared_ptr<Slot> slot, bool now);
  void OfferLocked(std::shared_ptr<Slot> slot, bool now);  // mutex_ held
  // options.stop or Stop() (relaxed loads: the tick asks too).
  bool StopAsked() const noexcept;
  void Publish();
  void Say(const std::string& line) const;

  const PluginRegistry& registry_;
  LiveSessionOptions options_;
  std::unique_ptr<TickPublisher> publisher_;
  std::unique_ptr<Server> server_;

  mutable std::mutex mutex_;                     // everything below up to the atomics
  std::shared_ptr<Slot> current_;                // the scene the running pass renders
  std::shared_ptr<Slot> pending_;                // prepared, waiting for a free part
  std::vector<std::shared_ptr<Slot>> compared_;  // a comparison's two scenes; empty for edits
  std::size_t selected_ = 0;                     // the compared scene rendering (or pending)
  nlohmann::json last_edit_;                     // what the last edit gave
  nlohmann::json panel_;                         // the newest panel message
  std::deque<std::string> inbox_;
  std::size_t busy_ = 0;  // messages taken but not yet handled
  bool closing_ = false;
  std::condition_variable wake_, idle_;

  // Read in the tick (relaxed loads): a scene waits to be swapped in; and at once.
  std::atomic<bool> swap_pending_{false};
  std::atomic<bool> swap_now_{false};
  std::atomic<bool> pass_stop_{false};
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> passes_{0}, swaps_{0};
  std::atomic<double> last_pass_peak_{0.0};
  std::thread worker_;
};

}  // namespace fitfeel::view
