#include "framework/view/server.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "framework/core/error.h"
#include "framework/view/assets.h"

namespace fitfeel::view {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Frame = std::shared_ptr<const std::string>;

// Every row when the run is short, else evenly spaced rows with the last one kept.
std::vector<ViewSample> Decimate(std::vector<ViewSample> rows, std::size_t max_rows) {
  if (rows.size() <= max_rows || max_rows < 2) return rows;
  std::vector<ViewSample> out;
  out.reserve(max_rows);
  for (std::size_t i = 0; i < max_rows; ++i) {
    out.push_back(rows[i * (rows.size() - 1) / (max_rows - 1)]);
  }
  return out;
}

}  // namespace

struct Server::Impl {
  struct Session;

  // What the server shows of one scene or one step of a sequence, and its run's newest state.
  struct Step {
    explicit Step(ServedStep served)
        : model(std::move(served.model)),
          publisher(served.publisher),
          scene_frame(std::make_shared<const std::string>(model->scene_message())) {
      for (int k = 0; k < model->mesh_count(); ++k) {
        mesh_frames.push_back(std::make_shared<const std::string>(model->mesh_frame(k)));
      }
      if (!served.history.empty()) SetHistory(std::move(served.history));
      if (served.companion) {
        companion_frames.push_back(
            std::make_shared<const std::string>(served.companion->companion_message()));
        for (int k = 0; k < served.companion->mesh_count(); ++k) {
          companion_frames.push_back(
              std::make_shared<const std::string>(served.companion->mesh_frame(k)));
        }
        companion = std::move(served.companion);
      }
    }

    void SetHistory(std::vector<ViewSample> rows) {
      history = Decimate(std::move(rows), kMaxHistoryRows);
      history_frame = std::make_shared<const std::string>(EncodeHistoryFrame(history));
      finished = true;
      if (!have_latest && !history.empty()) {
        latest = history.back();
        have_latest = true;
      }
    }

    Frame StateFrame(const ViewSample& sample) const {
      StateExtras extras = model->Extras(sample);
      extras.run_finished = finished;
      extras.dropped = publisher ? publisher->dropped() : 0;
      return std::make_shared<const std::string>(EncodeStateFrame(sample, extras));
    }

    std::shared_ptr<const ViewModel> model;
    TickPublisher* publisher;
    std::vector<ViewSample> history;
    Frame history_frame;
    bool finished = false;
    ViewSample latest;
    bool have_latest = false;
    Frame latest_frame;
    // Encoded once, queued to every client as the same buffers.
    const Frame scene_frame;
    std::vector<Frame> mesh_frames;  // filled by the constructor, read-only afterwards
    // A comparison's other scene: its marked scene message, then its meshes; kept alive with it.
    std::vector<Frame> companion_frames;
    std::shared_ptr<const ViewModel> companion;
  };

  Impl(std::vector<ServedStep> served, Frame sequence, const ServerOptions& o)
      : options(o), acceptor(io), timer(io), sequence_frame(std::move(sequence)) {
    steps.reserve(served.size());
    for (ServedStep& step : served) steps.push_back(std::make_shared<Step>(std::move(step)));
  }

  std::size_t newest() const { return steps.size() - 1; }

  bool OriginAllowed(std::string_view origin) const {
    if (origin.empty()) return true;  // not a browser: no cross-site page behind it
    const std::string port_text = ":" + std::to_string(bound_port);
    for (const std::string& host :
         {std::string("127.0.0.1"), std::string("localhost"), std::string("[::1]"), options.host}) {
      if (origin == "http://" + host + port_text) return true;
    }
    return false;
  }

  // Whether one more WebSocket client is served; when not, counts the refusal and, the first
  // time since the clients were fewer, says so on standard error.
  bool Admit(const std::string& peer) {
    if (clients.load(std::memory_order_relaxed) < options.max_clients) {
      refusing = false;
      return true;
    }
    refused.fetch_add(1, std::memory_order_relaxed);
    if (!refusing) {
      refusing = true;
      const std::string line =
          "fitfeel view: " + std::to_string(options.max_clients) +
          " viewer clients connected, the most served at once (--max-clients): refusing " + peer +
          " and any more until one leaves (HTTP 503)";
      if (options.log) {
        options.log(line);
      } else {
        std::fprintf(stderr, "%s\n", line.c_str());
        std::fflush(stderr);
      }
    }
    return false;
  }

  void Accept();
  void Pulse();
  void Collect(std::size_t k);
  void Broadcast(std::size_t k, const Frame& frame);
  void BeginStep(std::shared_ptr<Step> step, Frame sequence);
  void UpdateSequence(Frame sequence);
  void ReplaceScene(std::shared_ptr<Step> step);
  void UpdatePanel(Frame panel);

  ServerOptions options;
  // Before io: sessions that io's destructor destroys still count themselves out.
  std::atomic<std::uint64_t> frames_sent{0};
  std::atomic<int> clients{0};
  std::atomic<std::uint64_t> refused{0};
  bool refusing = false;  // the server thread's: refused since the clients were fewer
  asio::io_context io;
  tcp::acceptor acceptor;
  asio::steady_timer timer;
  std::thread thread;
  unsigned short bound_port = 0;
  std::vector<std::weak_ptr<Session>> sessions;
  // The scene's one step, or the sequence's steps begun so far; the server thread's once serving.
  // Held by pointer: a sequence's next step is built on the run's thread (its frames encoded
  // there, Server::BeginStep) and only handed over to this one.
  std::vector<std::shared_ptr<Step>> steps;
  Frame sequence_frame;  // null for a scene
  Frame panel_frame;     // a live session's newest panel message; null otherwise
};

// One WebSocket client. Frames the client must get (sequence, scene, meshes, history) queue in
// order; state frames share one slot that always holds the newest, so a slow client bounds its own
// memory. Every frame is the server's shared buffer (a seek's state frame excepted): queuing one
// copies a pointer. Nothing is queued before the handshake is done (a frame written then would
// mix with the handshake's response); the handshake's end queues everything the client is due.
struct Server::Impl::Session : std::enable_shared_from_this<Session> {
  Session(Impl& s, tcp::socket socket) : server(s), ws(std::move(socket)) {}
  ~Session() { server.clients.fetch_sub(1, std::memory_order_relaxed); }

  void Start(http::request<http::empty_body> request) {
    server.clients.fetch_add(1, std::memory_order_relaxed);
    step = server.newest();
    ws.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws.read_message_max(server.options.on_message ? kMaxEditMessage : kMaxClientMessage);
    ws.async_accept(request, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      self->open = true;
      if (self->server.sequence_frame) self->Queue(self->server.sequence_frame, true);
      self->Show(self->step);
      if (self->server.panel_frame) self->Queue(self->server.panel_frame, true);
      self->Read();
    });
  }

  // Step k from its scene message on: the frames of the step shown before that are still
  // waiting (its newest state, a seek's answer) are dropped, since they would land on k's parts.
  void Show(std::size_t k) {
    step = k;
    if (!open) return;
    pending_state.reset();
    const Step& s = *server.steps[k];
    Queue(s.scene_frame, true);
    for (const Frame& mesh : s.mesh_frames) Queue(mesh, false);
    for (std::size_t f = 0; f < s.companion_frames.size(); ++f) {
      Queue(s.companion_frames[f], f == 0);
    }
    if (s.history_frame) Queue(s.history_frame, false);
    if (s.latest_frame) Offer(s.latest_frame);
  }

  void Queue(Frame frame, bool text) {
    if (!open) return;
    queue.emplace_back(std::move(frame), text);
    Write();
  }

  void Offer(Frame state) {
    if (!open) return;
    pending_state = std::move(state);
    Write();
  }

  void Write() {
    if (writing || closed) return;
    Frame frame;
    bool text = false;
    if (!queue.empty()) {
      std::tie(frame, text) = std::move(queue.front());
      queue.pop_front();
    } else if (pending_state) {
      frame = std::move(pending_state);
      pending_state.reset();
      server.frames_sent.fetch_add(1, std::memory_order_relaxed);
    } else {
      return;
    }
    writing = true;
    ws.text(text);
    ws.binary(!text);
    ws.async_write(asio::buffer(*frame),
                   [self = shared_from_this(), frame](beast::error_code ec, std::size_t) {
                     self->writing = false;
                     if (ec) {
                       self->closed = true;  // gone: the weak pointer expires with it
                       return;
                     }
                     self->Write();
                   });
  }

  void Read() {
    ws.async_read(buffer, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) {
        self->closed = true;
        return;
      }
      const std::string message = beast::buffers_to_string(self->buffer.data());
      self->buffer.consume(self->buffer.size());
      self->Handle(message);
      self->Read();
    });
  }

  // "seek N": the state of row N of the shown step's finished history. "step N": a sequence's
  // begun step N, shown from its scene message on. Anything else goes to a live session's
  // handler, or is ignored.
  void Handle(const std::string& message) {
    const bool seek = message.rfind("seek ", 0) == 0;
    const bool step_message = message.rfind("step ", 0) == 0 && server.sequence_frame;
    if (!seek && !step_message) {
      if (server.options.on_message) server.options.on_message(message);
      return;
    }
    std::size_t n = 0;
    try {
      n = std::stoul(message.substr(5));
    } catch (const std::exception&) {
      return;
    }
    if (!seek) {
      if (n < server.steps.size() && n != step) Show(n);
      return;
    }
    const Step& s = *server.steps[step];
    if (n >= s.history.size()) return;
    Offer(s.StateFrame(s.history[n]));
  }

  Impl& server;
  websocket::stream<beast::tcp_stream> ws;
  beast::flat_buffer buffer;
  std::deque<std::pair<Frame, bool>> queue;
  Frame pending_state;
  std::size_t step = 0;  // the step shown: its state frames and seeks are this client's
  bool open = false;     // the handshake is done
  bool writing = false;
  bool closed = false;
};

namespace {

// One HTTP request per connection: the page's assets, or the upgrade to the WebSocket.
struct HttpSession : std::enable_shared_from_this<HttpSession> {
  using Upgrade = std::function<void(tcp::socket, http::request<http::empty_body>)>;
  HttpSession(tcp::socket socket, std::function<bool(std::string_view)> origin_ok,
              std::function<bool(const std::string&)> admit_client, Upgrade up)
      : stream(std::move(socket)),
        origin_allowed(std::move(origin_ok)),
        admit(std::move(admit_client)),
        upgrade(std::move(up)) {
    parser.header_limit(Server::kMaxRequestHeader);
    parser.body_limit(0);
  }

  void Start() {
    stream.expires_after(std::chrono::seconds(10));
    http::async_read(stream, buffer, parser,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) {
                       if (ec) {
                         // Oversized or malformed: say so once, then close.
                         if (ec != http::error::end_of_stream) self->Reply(400, "bad request\n");
                         return;
                       }
                       self->Handle();
                     });
  }

  void Handle() {
    auto request = parser.release();
    std::string_view target(request.target().data(), request.target().size());
    target = target.substr(0, target.find('?'));
    if (websocket::is_upgrade(request)) {
      if (target != "/ws") return Reply(404, "not found\n");
      const auto origin = request[http::field::origin];
      if (!origin_allowed(std::string_view(origin.data(), origin.size()))) {
        return Reply(403, "origin not allowed\n");
      }
      beast::error_code ec;
      const tcp::endpoint peer = stream.socket().remote_endpoint(ec);
      if (!admit(ec ? std::string("a client")
                    : peer.address().to_string() + ":" + std::to_string(peer.port()))) {
        return Reply(503,
                     "this viewer serves no more clients at once (--max-clients); close another "
                     "viewer page and reload\n");
      }
      stream.expires_never();
      return upgrade(stream.release_socket(), std::move(request));
    }
    if (request.method() != http::verb::get && request.method() != http::verb::head) {
      return Reply(405, "method not allowed\n");
    }
    const Asset* asset = FindAsset(target == "/" ? "/index.html" : target);
    if (asset == nullptr) return Reply(404, "not found\n");
    auto response = std::make_shared<http::response<http::string_body>>(http::status::ok, 11);
    response->set(http::field::content_type,
                  beast::string_view(asset->content_type.data(), asset->content_type.size()));
    response->set(http::field::cache_control, "no-store");
    response->set("X-Content-Type-Options", "nosniff");
    response->set("Content-Security-Policy",
                  "default-src 'self'; style-src 'self' 'unsafe-inline'; connect-src 'self'");
    if (request.method() == http::verb::get) response->body() = std::string(asset->body);
    response->content_length(asset->body.size());
    response->keep_alive(false);
    Send(response);
  }

  void Reply(unsigned status, const char* text) {
    auto response =
        std::make_shared<http::response<http::string_body>>(static_cast<http::status>(status), 11);
    response->set(http::field::content_type, "text/plain; charset=utf-8");
    response->body() = text;
    response->prepare_payload();
    response->keep_alive(false);
    Send(response);
  }

  void Send(const std::shared_ptr<http::response<http::string_body>>& response) {
    http::async_write(stream, *response,
                      [self = shared_from_this(), response](beast::error_code, std::size_t) {
                        beast::error_code ignored;
                        self->stream.socket().shutdown(tcp::socket::shutdown_send, ignored);
                      });
  }

  beast::tcp_stream stream;
  beast::flat_buffer buffer;
  http::request_parser<http::empty_body> parser;
  std::function<bool(std::string_view)> origin_allowed;
  std::function<bool(const std::string&)> admit;
  Upgrade upgrade;
};

}  // namespace

void Server::Impl::Accept() {
  acceptor.async_accept(io, [this](beast::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted) return;
    if (!ec) {
      auto session = std::make_shared<HttpSession>(
          std::move(socket), [this](std::string_view origin) { return OriginAllowed(origin); },
          [this](const std::string& peer) { return Admit(peer); },
          [this](tcp::socket s, http::request<http::empty_body> request) {
            auto ws = std::make_shared<Session>(*this, std::move(s));
            sessions.push_back(ws);
            ws->Start(std::move(request));
          });
      session->Start();
    }
    Accept();
  });
}

void Server::Impl::Broadcast(std::size_t k, const Frame& frame) {
  sessions.erase(std::remove_if(sessions.begin(), sessions.end(),
                                [](const std::weak_ptr<Session>& s) { return s.expired(); }),
                 sessions.end());
  for (auto& weak : sessions) {
    if (auto s = weak.lock(); s && s->step == k) s->Offer(frame);
  }
}

// Step k's newest sample, and its history once its run ended, to the clients on it. Every step
// is collected, not only the newest: an earlier step's history may come after the next step began.
void Server::Impl::Collect(std::size_t k) {
  Step& s = *steps[k];
  bool fresh = false;
  if (s.publisher != nullptr) {
    ViewSample sample;
    if (s.publisher->PopLatest(&sample)) {
      s.latest = sample;
      s.have_latest = fresh = true;
    }
    if (auto rows = s.publisher->TakeHistory()) {
      s.SetHistory(std::move(*rows));
      for (auto& weak : sessions) {
        if (auto session = weak.lock(); session && session->step == k) {
          session->Queue(s.history_frame, false);
        }
      }
      fresh = s.have_latest;
    }
  }
  if (fresh || (s.have_latest && !s.latest_frame)) {
    s.latest_frame = s.StateFrame(s.latest);
    Broadcast(k, s.latest_frame);
  }
}

// Display rate: each step's newest sample becomes one state frame for every client on it.
void Server::Impl::Pulse() {
  for (std::size_t k = 0; k < steps.size(); ++k) Collect(k);
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / options.frame_rate));
  timer.expires_after(period);
  timer.async_wait([this](beast::error_code ec) {
    if (!ec) Pulse();
  });
}

void Server::Impl::BeginStep(std::shared_ptr<Step> step, Frame sequence) {
  const std::size_t before = newest();
  steps.push_back(std::move(step));
  sequence_frame = std::move(sequence);
  for (auto& weak : sessions) {
    auto s = weak.lock();
    if (!s) continue;
    s->Queue(sequence_frame, true);
    if (s->step == before) s->Show(newest());
  }
}

void Server::Impl::UpdateSequence(Frame sequence) {
  sequence_frame = std::move(sequence);
  for (auto& weak : sessions) {
    if (auto s = weak.lock()) s->Queue(sequence_frame, true);
  }
}

void Server::Impl::ReplaceScene(std::shared_ptr<Step> step) {
  const std::size_t shown = newest();
  // The samples waiting are the scene's before (its pass ended before this was posted): drawn on
  // the new scene's parts they would show the old scene's forces.
  ViewSample stale;
  if (step->publisher != nullptr) step->publisher->PopLatest(&stale);
  steps[shown] = std::move(step);
  for (auto& weak : sessions) {
    if (auto s = weak.lock(); s && s->step == shown) s->Show(shown);
  }
}

void Server::Impl::UpdatePanel(Frame panel) {
  panel_frame = std::move(panel);
  for (auto& weak : sessions) {
    if (auto s = weak.lock()) s->Queue(panel_frame, true);
  }
}

namespace {

void CheckOptions(const ServerOptions& options) {
  if (!(options.frame_rate >= 1.0 && options.frame_rate <= 240.0)) {
    throw UserError("viewer frame rate must be in [1, 240] Hz");
  }
  if (options.max_clients < 1 || options.max_clients > Server::kMaxClientsCap) {
    throw UserError("viewer: --max-clients must be in 1.." +
                    std::to_string(Server::kMaxClientsCap) + ", got " +
                    std::to_string(options.max_clients));
  }
}

}  // namespace

Server::Server(const ViewModel& model, TickPublisher* publisher, std::vector<ViewSample> history,
               const ServerOptions& options) {
  CheckOptions(options);
  // The model is borrowed: a shared pointer that owns nothing.
  std::vector<ServedStep> steps(1);
  steps[0].model = std::shared_ptr<const ViewModel>(std::shared_ptr<const ViewModel>(), &model);
  steps[0].publisher = publisher;
  steps[0].history = std::move(history);
  impl_ = std::make_unique<Impl>(std::move(steps), nullptr, options);
}

Server::Server(ServedStep scene, const ServerOptions& options) {
  CheckOptions(options);
  if (!scene.model) throw UserError("viewer: a scene's server needs its view model");
  std::vector<ServedStep> steps(1);
  steps[0] = std::move(scene);
  impl_ = std::make_unique<Impl>(std::move(steps), nullptr, options);
}

Server::Server(std::vector<ServedStep> steps, std::string sequence_message,
               const ServerOptions& options) {
  CheckOptions(options);
  if (steps.empty()) throw UserError("viewer: a sequence's server needs its first step");
  for (const ServedStep& step : steps) {
    if (!step.model) throw UserError("viewer: a sequence's step has no view model");
  }
  impl_ = std::make_unique<Impl>(
      std::move(steps), std::make_shared<const std::string>(std::move(sequence_message)), options);
}

Server::~Server() { Stop(); }

void Server::Start() {
  Impl& s = *impl_;
  beast::error_code ec;
  const auto address = asio::ip::make_address(s.options.host, ec);
  if (ec) {
    throw UserError("viewer: '" + s.options.host + "' is not an IP address (" + ec.message() + ")");
  }
  const tcp::endpoint endpoint(address, s.options.port);
  s.acceptor.open(endpoint.protocol(), ec);
  if (!ec) s.acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) s.acceptor.bind(endpoint, ec);
  if (!ec) s.acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) {
    throw UserError("viewer: cannot listen on " + s.options.host + ":" +
                    std::to_string(s.options.port) + ": " + ec.message());
  }
  s.bound_port = s.acceptor.local_endpoint().port();
  s.Accept();
  asio::post(s.io, [&s] { s.Pulse(); });
  s.thread = std::thread([&s] { s.io.run(); });
}

void Server::Stop() {
  if (!impl_ || !impl_->thread.joinable()) return;
  asio::post(impl_->io, [this] {
    beast::error_code ignored;
    impl_->acceptor.close(ignored);
    impl_->timer.cancel();
    impl_->io.stop();
  });
  impl_->thread.join();
}

void Server::BeginStep(ServedStep step, std::string sequence_message) {
  if (!step.model) throw UserError("viewer: a sequence's step has no view model");
  auto frame = std::make_shared<const std::string>(std::move(sequence_message));
  // The step's frames are made here, on the caller's thread; the server's thread only takes them.
  auto served = std::make_shared<Impl::Step>(std::move(step));
  asio::post(impl_->io, [impl = impl_.get(), served, frame]() mutable {
    impl->BeginStep(std::move(served), std::move(frame));
  });
}

void Server::UpdateSequence(std::string sequence_message) {
  auto frame = std::make_shared<const std::string>(std::move(sequence_message));
  asio::post(impl_->io,
             [impl = impl_.get(), frame]() mutable { impl->UpdateSequence(std::move(frame)); });
}

void Server::ReplaceScene(ServedStep step) {
  if (!step.model) throw UserError("viewer: a live session's scene has no view model");
  auto served = std::make_shared<Impl::Step>(std::move(step));
  asio::post(impl_->io,
             [impl = impl_.get(), served]() mutable { impl->ReplaceScene(std::move(served)); });
}

void Server::UpdatePanel(std::string panel_message) {
  auto frame = std::make_shared<const std::string>(std::move(panel_message));
  asio::post(impl_->io,
             [impl = impl_.get(), frame]() mutable { impl->UpdatePanel(std::move(frame)); });
}

unsigned short Server::port() const { return impl_->bound_port; }
std::uint64_t Server::frames_sent() const {
  return impl_->frames_sent.load(std::memory_order_relaxed);
}
int Server::clients() const { return impl_->clients.load(std::memory_order_relaxed); }
std::uint64_t Server::clients_refused() const {
  return impl_->refused.load(std::memory_order_relaxed);
}

}  // namespace fitfeel::view
