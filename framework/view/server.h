#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/view/tick_publisher.h"
#include "framework/view/view_model.h"

namespace fitfeel::view {

struct ServerOptions {
  std::string host = "127.0.0.1";  // loopback unless told otherwise
  unsigned short port = 0;         // 0: a free port (see Server::port)
  double frame_rate = 60.0;        // state frames per second, Hz
  // WebSocket clients served at once, in [1, Server::kMaxClientsCap]; one more is answered 503.
  // Each costs the server's one thread a state frame per display period (0.9 MB/s at the paper's
  // grid and 60 Hz): 64 browsers, a classroom, take 55 MB/s.
  int max_clients = 64;
  // Receives the server's notices, a line each without its line break, on the server's thread;
  // empty: standard error.
  std::function<void(const std::string&)> log;
  // A live session's (LiveSession): receives every client message the server does not answer
  // itself (anything but `seek N` and `step N`), on the server's thread; it must hand the work
  // over and return at once. Empty: such messages are ignored. With it, a client message may be
  // up to kMaxEditMessage bytes (an edit's key paths and values), else kMaxClientMessage.
  std::function<void(const std::string&)> on_message;
};

// One step of a sequence (docs/assemblies.md) as the server shows it: its parts (the model, which
// the server keeps alive) and its run, live through its publisher or finished as its history.
struct ServedStep {
  std::shared_ptr<const ViewModel> model;
  // The step's live run; borrowed, must outlive the server. Null for a finished step.
  TickPublisher* publisher = nullptr;
  // A finished step's rows (a finished sequence opened with --trace), or empty.
  std::vector<ViewSample> history;
  // A comparison's other scene (LiveSession): drawn beside this one and not run. Its scene
  // message (with `companion`: true) and meshes follow this scene's; null for none.
  std::shared_ptr<const ViewModel> companion;
};

// The viewer's HTTP and WebSocket server (Boost.Beast on one thread of its own): the page and its
// scripts at fixed paths (anything else 404), the WebSocket at /ws (Origin checked against the
// served host, messages from the browser at most kMaxClientMessage bytes). Every client gets the
// scene message, both mesh frames, then state frames at `frame_rate` sampled from the publisher,
// and the history of a finished run once there is one. The scene message, the mesh frames, the
// history and each state frame are encoded once and shared by every client that has them waiting,
// so a client costs its socket and a few pointers, not copies of the frames. A client that is
// slower than the frames keeps at most one state frame waiting (the newest); one that disconnects
// is dropped. Beyond `max_clients` an upgrade is answered 503 with a text body, and a line on
// standard error says so (once, until a client is served again).
//
// A sequence's server shows its steps, each as a scene: the sequence message (JSON text, the
// steps and what each finished one left) first, then the scene message, meshes, history and state
// of the step the client is on. A client starts on the newest step (the one the run is in) and
// moves on with the run: when the next step begins, each client on the step before gets the new
// sequence message and the new step's scene message and meshes, so the page draws the new step's
// parts from its scene message on as it draws a scene. A client may ask for any begun step
// (`step N`, from 0), which it then gets the same way; state frames and seeks are its step's.
class FITFEEL_API Server {
 public:
  static constexpr std::size_t kMaxClientMessage = 256;
  static constexpr std::size_t kMaxEditMessage = 8192;
  static constexpr std::size_t kMaxRequestHeader = 8192;
  static constexpr std::size_t kMaxHistoryRows = 4000;
  static constexpr int kMaxClientsCap = 4096;

  // `publisher` (live run, may be null) and `model` are borrowed and must outlive the server.
  // `history`: the rows of a finished run to serve (opened with --trace), or empty. Throws
  // UserError for a frame rate outside [1, 240] Hz or max_clients outside [1, kMaxClientsCap].
  Server(const ViewModel& model, TickPublisher* publisher, std::vector<ViewSample> history,
         const ServerOptions& options);
  // A scene whose model the server shares (a live session's, whose scene is replaced while the
  // server serves it). Throws as the constructor above does, and UserError for no model.
  Server(ServedStep scene, const ServerOptions& options);
  // A sequence's: its steps so far, the last the one the run is in (every step of a finished
  // sequence), and the sequence message. Throws as the scene's constructor does, and UserError for
  // no step or a step without a model.
  Server(std::vector<ServedStep> steps, std::string sequence_message,
         const ServerOptions& options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Binds and starts serving on a thread of its own. Throws UserError when the address cannot be
  // bound (naming it and why).
  void Start();
  // Stops serving and joins the thread; idempotent.
  void Stop();
  // A sequence's run begins its next step: from the server's thread on, `step` is the newest, and
  // the clients on the step before move to it with `sequence_message`. Any thread; the step's
  // publisher may be reporting ticks already.
  void BeginStep(ServedStep step, std::string sequence_message);
  // A sequence's message changed (a step finished): every client gets it. Any thread.
  void UpdateSequence(std::string sequence_message);
  // A live session's scene changed (an edit applied, the other scene of a comparison selected):
  // the newest step becomes `step`, and every client on it gets its scene message and meshes, as
  // a sequence's next step is shown. Any thread.
  void ReplaceScene(ServedStep step);
  // A live session's panel (JSON text: what can be edited, what the last edit gave, which scene
  // of a comparison renders): every client gets it now, and each client that connects later gets
  // the newest one after its scene. Any thread.
  void UpdatePanel(std::string panel_message);
  unsigned short port() const;
  // State frames handed to clients so far, and clients connected (any thread; for tests and the
  // command's summary).
  std::uint64_t frames_sent() const;
  int clients() const;
  // WebSocket upgrades answered 503 because max_clients were connected (any thread).
  std::uint64_t clients_refused() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fitfeel::view
