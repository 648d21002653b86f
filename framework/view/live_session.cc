#include "framework/view/live_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <future>
#include <sstream>
#include <utility>

#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/quantity.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene_summary.h"
#include "framework/scenario/sequence.h"
#include "framework/scenario/yaml_file.h"
#include "framework/view/scene_edits.h"
#include "framework/view/view_model.h"

namespace fitfeel::view {
namespace {

using Clock = std::chrono::steady_clock;

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UserError("view: cannot read '" + file.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The fit of a one-feature scene's two ISO 286 sizes ("H7/js6"), or empty.
std::string FitOf(const std::vector<EditableField>& fields) {
  std::string hole, shaft;
  for (const EditableField& f : fields) {
    if (f.iso_class.empty()) continue;
    (std::isupper(static_cast<unsigned char>(f.iso_class[0])) ? hole : shaft) = f.iso_class;
  }
  return hole.empty() || shaft.empty() ? std::string() : hole + "/" + shaft;
}

}  // namespace

struct LiveSession::Slot {
  std::string label;  // a comparison's "A" or "B"; empty for an edited scene
  std::string yaml;
  std::filesystem::path file;
  Scene scene;
  PreparedScene prepared;
  std::shared_ptr<const ViewModel> model;
  std::vector<EditableField> fields;
  double prepare_ms = 0.0;  // wall time of the preparation and the view model, made side by side
};

// Hands the tick to the page (the publisher's ring) and ends the pass at the first tick where a
// scene waits and the moving part is out of contact, or at once when asked. In the tick: relaxed
// loads and stores only.
class LiveSession::PassObserver final : public TickObserver {
 public:
  explicit PassObserver(LiveSession& session) : s_(session) {}
  void OnTick(const TickRecord& record) noexcept override {
    s_.publisher_->OnTick(record);
    if (record.stage == StageId::kConstrained)
      peak = std::max(peak, std::abs(record.wrench.force.y()));
    const bool free = record.stage == StageId::kPositioning || !record.contact.engaged;
    if (s_.StopAsked() || (s_.swap_pending_.load(std::memory_order_acquire) &&
                           (free || s_.swap_now_.load(std::memory_order_relaxed)))) {
      s_.pass_stop_.store(true, std::memory_order_relaxed);
    }
  }

  double peak = 0.0;  // the pass's largest axial resistance, N

 private:
  LiveSession& s_;
};

LiveSession::LiveSession(const std::filesystem::path& file,
                         const std::optional<std::filesystem::path>& compare,
                         const PluginRegistry& registry, LiveSessionOptions options)
    : registry_(registry), options_(std::move(options)) {
  current_ = OpenSlot(file, compare ? "A" : "");
  if (compare) {
    compared_ = {current_, OpenSlot(*compare, "B")};
    if (compared_[1]->scene.moving != current_->scene.moving) {
      throw UserError("view: '" + file.string() + "' and '" + compare->string() +
                      "' move different parts; a comparison renders one moving part");
    }
  }
  publisher_ = std::make_unique<TickPublisher>(1024, current_->scene.moving);
  ServerOptions server = options_.server;
  server.on_message = [this](const std::string& message) { Submit(message); };
  ServedStep step;
  step.model = current_->model;
  step.publisher = publisher_.get();
  if (compare) step.companion = compared_[1]->model;
  server_ = std::make_unique<Server>(std::move(step), server);
  Publish();
  worker_ = std::thread([this] { Work(); });
}

LiveSession::~LiveSession() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
  if (server_) server_->Stop();
}

std::shared_ptr<LiveSession::Slot> LiveSession::OpenSlot(const std::filesystem::path& file,
                                                         const std::string& label) const {
  if (IsSequenceFile(file)) {
    throw UserError("view: '" + file.string() +
                    "' is a sequence; a live view edits or compares scenes (run the sequence "
                    "with fitfeel view without --edit or --compare)");
  }
  // Loaded as validate loads it, so that its errors point into the file itself.
  Scene scene = LoadScene(file, registry_, options_.load);
  std::string yaml = ReadText(file);
  if (options_.seed) {
    // The text too: the page edits on from it.
    yaml = ApplyEdits(yaml, file.string(), {{"run.seed", std::to_string(*options_.seed)}});
    scene.run.seed = *options_.seed;
  }
  return MakeSlot(std::move(yaml), std::move(scene), file, label);
}

std::shared_ptr<LiveSession::Slot> LiveSession::MakeSlot(std::string yaml, Scene loaded,
                                                         const std::filesystem::path& file,
                                                         const std::string& label) const {
  const auto start = Clock::now();
  auto slot = std::make_shared<Slot>();
  slot->label = label;
  slot->file = file;
  slot->fields = EditableFields(yaml, file.string());
  slot->scene = std::move(loaded);
  slot->yaml = std::move(yaml);
  slot->scene.run.clock = options_.clock;
  const Scene& scene = slot->scene;
  if (!scene.device) throw UserError("scene '" + scene.name + "' has no device");
  // The view's model draws the same shapes on a thread of its own while the run's are prepared.
  // In real time both are ready to touch when they return and prepare the rest of their tables
  // on threads of their own, as a run in real time does: a swap waits for neither's whole tables.
  // Virtual time (tests) has no deadline and prepares them whole.
  const bool progressive = options_.clock == ClockMode::kRealTime;
  std::future<std::shared_ptr<const ViewModel>> model =
      std::async(std::launch::async, [&scene, progressive] {
        return std::shared_ptr<const ViewModel>(
            std::make_shared<ViewModel>(scene, scene.run.seed, -1, progressive));
      });
  ProgressiveSettings settings;
  settings.worker = progressive;
  slot->prepared =
      PrepareProgressive(scene, settings, nullptr, scene.device->reach(scene.run.duration),
                         scene.device->angular_reach(scene.run.duration));
  if (!progressive) slot->prepared.FinishPreparing();
  slot->model = model.get();
  if (!slot->model->renders_forces()) {
    throw UnsupportedError("view: scene '" + scene.name + "' renders no forces (" +
                           slot->model->status() + "): a live view runs it");
  }
  slot->prepare_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return slot;
}

void LiveSession::Run(std::optional<std::uint64_t> passes) {
  PassObserver observer(*this);
  while (!StopAsked() && !(passes && passes_.load() >= *passes)) {
    std::shared_ptr<Slot> slot;
    bool swapped = false;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (swap_pending_.load() && pending_) {
        current_ = std::move(pending_);
        if (!compared_.empty()) selected_ = current_ == compared_[0] ? 0 : 1;
        swap_pending_.store(false);
        swap_now_.store(false);
        swapped = true;
        if (compared_.empty() && last_edit_.contains("prepare_ms")) last_edit_["state"] = "applied";
      }
      slot = current_;
    }
    if (swapped) {
      ServedStep step;
      step.model = slot->model;
      step.publisher = publisher_.get();
      if (!compared_.empty()) step.companion = compared_[slot == compared_[0] ? 1 : 0]->model;
      server_->ReplaceScene(std::move(step));
      swaps_.fetch_add(1);
      Say("  renders " + slot->scene.name + (slot->label.empty() ? "" : " (" + slot->label + ")"));
      Publish();
    }
    pass_stop_.store(false);
    observer.peak = 0.0;
    RunOptions run;
    run.stop = &pass_stop_;
    run.observer = &observer;
    try {
      RunPreparedScene(slot->scene, slot->prepared, run);
    } catch (const Interrupted&) {
      // A swap or a stop ended the pass at a tick boundary; nothing was written.
    }
    last_pass_peak_.store(observer.peak);
    passes_.fetch_add(1);
    Publish();
  }
}

void LiveSession::Submit(const std::string& message) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    // A page sends a message a click; a flood is bounded (each message is at most 8 KiB).
    if (inbox_.size() >= kMaxWaitingMessages) return;
    inbox_.push_back(message);
  }
  wake_.notify_all();
}

void LiveSession::Drain() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return inbox_.empty() && busy_ == 0; });
}

void LiveSession::Work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return closing_ || !inbox_.empty(); });
    if (closing_) return;
    const std::string message = std::move(inbox_.front());
    inbox_.pop_front();
    ++busy_;
    lock.unlock();
    try {
      Handle(message);
    } catch (const std::exception& e) {
      // A message of the wrong shape ("now": "yes"): said in the page, the session goes on.
      {
        const std::lock_guard<std::mutex> refused(mutex_);
        last_edit_ = {
            {"state", "refused"},
            {"message", std::string("view: a message the session cannot take: ") + e.what()}};
      }
      Publish();
    }
    lock.lock();
    --busy_;
    idle_.notify_all();
  }
}

void LiveSession::Handle(const std::string& message) {
  const nlohmann::json j = nlohmann::json::parse(message, nullptr, /*allow_exceptions=*/false);
  const std::string type = j.is_object() && j.contains("type") && j["type"].is_string()
                               ? j["type"].get<std::string>()
                               : "";
  if (type == "edit" && compared_.empty()) {
    HandleEdit(j);
  } else if (type == "apply") {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (pending_) swap_now_.store(true);
  } else if (type == "select" && !compared_.empty() && j.contains("scene") &&
             j["scene"].is_number_unsigned() && j["scene"].get<std::size_t>() < 2) {
    const std::size_t k = j["scene"].get<std::size_t>();
    const bool now = j.value("now", false);
    const std::lock_guard<std::mutex> lock(mutex_);
    selected_ = k;
    if (compared_[k] == current_) {
      // Selecting the scene that renders withdraws a switch still waiting.
      pending_.reset();
      swap_pending_.store(false);
      swap_now_.store(false);
    } else {
      OfferLocked(compared_[k], now);
    }
  } else {
    const std::lock_guard<std::mutex> lock(mutex_);
    last_edit_ = {{"state", "refused"},
                  {"message", "view: the session takes edit, apply and select messages (JSON)"}};
  }
  Publish();
}

void LiveSession::HandleEdit(const nlohmann::json& message) {
  std::map<std::string, std::string> edits;
  std::string apply = "check";
  std::shared_ptr<Slot> base;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    base = pending_ ? pending_ : current_;
  }
  const std::string name = base->file.string();
  try {
    if (!message.contains("edits") || !message["edits"].is_object()) {
      throw UserError("view: an edit message carries `edits`, an object of key path: value");
    }
    for (const auto& [path, value] : message["edits"].items()) {
      edits[path] = value.is_string() ? value.get<std::string>() : value.dump();
    }
    if (message.contains("apply") && message["apply"].is_string()) apply = message["apply"];
    if (apply != "check" && apply != "free" && apply != "now") {
      throw UserError("view: an edit's `apply` is check, free or now, not '" + apply + "'");
    }
    std::string yaml = ApplyEdits(base->yaml, name, edits);
    Scene checked = LoadSceneFromYaml(yaml, base->file, registry_, options_.load);
    nlohmann::json result = {
        {"state", "valid"}, {"described", DescribeScene(checked)}, {"edits", edits}};
    if (apply != "check") {
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        last_edit_ = {{"state", "preparing"}, {"edits", edits}};
      }
      Publish();
      std::shared_ptr<Slot> slot = MakeSlot(std::move(yaml), std::move(checked), base->file, "");
      result["state"] = apply == "now" ? "swapping" : "waiting for the part to be out of contact";
      result["prepare_ms"] = slot->prepare_ms;
      Say("  edit prepared in " + std::to_string(static_cast<int>(slot->prepare_ms)) +
          " ms: " + nlohmann::json(edits).dump());
      Offer(std::move(slot), apply == "now");
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    last_edit_ = std::move(result);
  } catch (const ScenarioError& e) {
    const std::lock_guard<std::mutex> lock(mutex_);
    last_edit_ = {{"state", "refused"},       {"message", e.what()}, {"key_path", e.key_path()},
                  {"expected", e.expected()}, {"found", e.found()},  {"edits", edits}};
  } catch (const UserError& e) {
    const std::lock_guard<std::mutex> lock(mutex_);
    last_edit_ = {{"state", "refused"}, {"message", e.what()}, {"edits", edits}};
  }
}

void LiveSession::Offer(std::shared_ptr<Slot> slot, bool now) {
  const std::lock_guard<std::mutex> lock(mutex_);
  OfferLocked(std::move(slot), now);
}

void LiveSession::OfferLocked(std::shared_ptr<Slot> slot, bool now) {
  pending_ = std::move(slot);
  swap_now_.store(now);
  swap_pending_.store(true, std::memory_order_release);
}

void LiveSession::Publish() {
  nlohmann::json panel;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::shared_ptr<Slot>& newest = pending_ ? pending_ : current_;
    panel = {{"type", "live"},
             {"mode", compared_.empty() ? "edit" : "compare"},
             {"scene", current_->scene.name},
             {"file", current_->file.filename().string()},
             {"fields", FieldsJson(newest->fields)},
             {"yaml", newest->yaml},
             {"edit", last_edit_},
             {"pending", pending_ != nullptr},
             {"passes", passes_.load()},
             {"last_pass_peak_N", last_pass_peak_.load()},
             {"swaps", swaps_.load()}};
    nlohmann::json fits = nlohmann::json::array();
    for (const EditableField& f : newest->fields) {
      if (f.nominal.empty()) continue;
      try {
        fits = FitsAt(ParseQuantity(f.nominal, Dimension::kLength));
      } catch (const std::exception&) {
        fits = nlohmann::json::array();
      }
      break;
    }
    panel["fits"] = fits;
    panel["fit"] = FitOf(newest->fields);
    if (!compared_.empty()) {
      nlohmann::json scenes = nlohmann::json::array();
      for (const std::shared_ptr<Slot>& s : compared_) {
        scenes.push_back({{"label", s->label},
                          {"scene", s->scene.name},
                          {"file", s->file.filename().string()},
                          {"fit", FitOf(s->fields)},
                          {"prepare_ms", s->prepare_ms}});
      }
      panel["compare"] = {{"scenes", scenes},
                          {"rendering", current_ == compared_[0] ? 0 : 1},
                          {"selected", selected_}};
    }
  }
  server_->UpdatePanel(panel.dump());
  const std::lock_guard<std::mutex> lock(mutex_);
  panel_ = std::move(panel);
}

nlohmann::json LiveSession::panel() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return panel_;
}

std::string LiveSession::rendering() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return (pending_ && swap_pending_.load() ? pending_ : current_)->scene.name;
}

bool LiveSession::StopAsked() const noexcept {
  return stop_.load(std::memory_order_relaxed) ||
         (options_.stop != nullptr && options_.stop->load(std::memory_order_relaxed));
}

void LiveSession::Say(const std::string& line) const {
  if (options_.say) options_.say(line);
}

}  // namespace fitfeel::view
