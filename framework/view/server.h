#pragma once

#include <atomic>
#include <cstdint>
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
};

// The viewer's HTTP and WebSocket server (Boost.Beast on one thread of its own): the page and its
// scripts at fixed paths (anything else 404), the WebSocket at /ws (Origin checked against the
// served host, messages from the browser at most kMaxClientMessage bytes). Every client gets the
// scene message, both mesh frames, then state frames at `frame_rate` sampled from the publisher,
// and the history of a finished run once there is one. A client that is slower than the frames
// keeps at most one state frame waiting (the newest); one that disconnects is dropped.
class FITFEEL_API Server {
 public:
  static constexpr std::size_t kMaxClientMessage = 256;
  static constexpr std::size_t kMaxRequestHeader = 8192;
  static constexpr std::size_t kMaxHistoryRows = 4000;

  // `publisher` (live run, may be null) and `model` are borrowed and must outlive the server.
  // `history`: the rows of a finished run to serve (opened with --trace), or empty.
  Server(const ViewModel& model, TickPublisher* publisher, std::vector<ViewSample> history,
         const ServerOptions& options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Binds and starts serving on a thread of its own. Throws UserError when the address cannot be
  // bound (naming it and why).
  void Start();
  // Stops serving and joins the thread; idempotent.
  void Stop();
  unsigned short port() const;
  // State frames handed to clients so far, and clients connected (any thread; for tests and the
  // command's summary).
  std::uint64_t frames_sent() const;
  int clients() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fitfeel::view
