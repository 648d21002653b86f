#include "framework/view/server.h"

#include <chrono>
#include <string>
#include <thread>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <gtest/gtest.h>

#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/view/assets.h"
#include "framework/view/frame_codec.h"

namespace fitfeel::view {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

// One viewer server on a free loopback port over the paper's case study, shared by the tests.
class ServerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    registry_ = new PluginRegistry();
    registry_->LoadAll();
    const Scene scene = LoadScene("scenarios/paper-case1-h7js6.yaml", *registry_);
    model_ = new ViewModel(scene, 1);
    publisher_ = new TickPublisher();
    server_ = new Server(*model_, publisher_, {}, ServerOptions{});
    server_->Start();
  }
  static void TearDownTestSuite() {
    delete server_;
    delete publisher_;
    delete model_;
    delete registry_;
  }

  // The raw response to a raw request line (no client-side normalisation of the path).
  static std::string Raw(const std::string& request) {
    asio::io_context io;
    tcp::socket socket(io);
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
    asio::write(socket, asio::buffer(request));
    std::string response;
    beast::error_code ec;
    char chunk[4096];
    // To the end of the stream, or of the head of a response that keeps the connection (101).
    for (;;) {
      const std::size_t n = socket.read_some(asio::buffer(chunk), ec);
      response.append(chunk, n);
      if (ec || (response.rfind("HTTP/1.1 101", 0) == 0 &&
                 response.find("\r\n\r\n") != std::string::npos)) {
        break;
      }
    }
    return response;
  }
  static std::string Get(const std::string& target) {
    return Raw("GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  }
  static std::string Origin() { return "http://127.0.0.1:" + std::to_string(server_->port()); }

  static PluginRegistry* registry_;
  static ViewModel* model_;
  static TickPublisher* publisher_;
  static Server* server_;
};
PluginRegistry* ServerTest::registry_ = nullptr;
ViewModel* ServerTest::model_ = nullptr;
TickPublisher* ServerTest::publisher_ = nullptr;
Server* ServerTest::server_ = nullptr;

TEST_F(ServerTest, ServesThePageAndThreeJs) {
  const std::string page = Get("/");
  EXPECT_EQ(page.rfind("HTTP/1.1 200", 0), 0u) << page.substr(0, 200);
  EXPECT_NE(page.find("<title>fitfeel view</title>"), std::string::npos);
  EXPECT_NE(page.find("Content-Type: text/html"), std::string::npos);
  const std::string three = Get("/three/build/three.module.js");
  EXPECT_EQ(three.rfind("HTTP/1.1 200", 0), 0u);
  EXPECT_NE(three.find("WebGLRenderer"), std::string::npos);
  EXPECT_EQ(Get("/viewer.js?v=1").rfind("HTTP/1.1 200", 0), 0u);  // a query is not part of a path
  ASSERT_NE(FindAsset("/three/examples/jsm/controls/OrbitControls.js"), nullptr);
}

TEST_F(ServerTest, AnythingButItsOwnAssetsIs404) {
  for (const char* target : {"/../../etc/passwd", "/etc/passwd", "/..%2F..%2Fetc%2Fpasswd",
                             "/three/../../../../etc/passwd", "/index.html/..", "/nope",
                             "//etc/passwd", "/three/build/", "/ws"}) {
    const std::string r = Get(target);
    EXPECT_EQ(r.rfind("HTTP/1.1 404", 0), 0u) << target << ": " << r.substr(0, 80);
    EXPECT_EQ(r.find("root:"), std::string::npos) << target;
  }
  EXPECT_EQ(Raw("POST / HTTP/1.1\r\nHost: x\r\n\r\n").rfind("HTTP/1.1 405", 0), 0u);
}

TEST_F(ServerTest, OversizedAndMalformedRequestsAreRefusedAndServingGoesOn) {
  const std::string big(2 * Server::kMaxRequestHeader, 'a');
  EXPECT_EQ(Raw("GET / HTTP/1.1\r\nX-Big: " + big + "\r\n\r\n").rfind("HTTP/1.1 400", 0), 0u);
  EXPECT_EQ(Raw("NONSENSE\r\n\r\n").rfind("HTTP/1.1 400", 0), 0u);
  EXPECT_EQ(Raw("POST / HTTP/1.1\r\nContent-Length: 100000\r\n\r\n").rfind("HTTP/1.1 4", 0), 0u);
  EXPECT_EQ(Get("/").rfind("HTTP/1.1 200", 0), 0u);
}

TEST_F(ServerTest, WebSocketHandshakeGets101ThenSceneMeshesAndState) {
  asio::io_context io;
  websocket::stream<tcp::socket> ws(io);
  ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
  ws.set_option(websocket::stream_base::decorator(
      [](websocket::request_type& r) { r.set(http::field::origin, Origin()); }));
  websocket::response_type response;
  ws.handshake(response, "127.0.0.1", "/ws");
  EXPECT_EQ(response.result_int(), 101);

  beast::flat_buffer buffer;
  ws.read(buffer);
  EXPECT_TRUE(ws.got_text());
  const std::string scene = beast::buffers_to_string(buffer.data());
  EXPECT_NE(scene.find("\"type\":\"scene\""), std::string::npos);
  EXPECT_NE(scene.find("paper-case1-h7js6"), std::string::npos);
  for (int part : {0, 1}) {
    buffer.consume(buffer.size());
    ws.read(buffer);
    EXPECT_TRUE(ws.got_binary());
    EXPECT_EQ(beast::buffers_to_string(buffer.data()), model_->mesh_frame(part));
  }
  // A tick at 10 mm depth in the transition fit's interference: its state reaches the client
  // with a pressure map over the shaft's cells.
  TickRecord record;
  record.time = 1.0;
  record.pose.depth = 10e-3;
  record.stage = StageId::kConstrained;
  record.wrench.force = Eigen::Vector3d(0.0, -50.0, 2.0);
  publisher_->OnTick(record);
  DecodedState state;
  for (int i = 0; i < 100; ++i) {
    buffer.consume(buffer.size());
    ws.read(buffer);
    state = DecodeStateFrame(beast::buffers_to_string(buffer.data()));
    if (state.sample.time == 1.0) break;
  }
  EXPECT_EQ(state.sample.time, 1.0);
  EXPECT_FLOAT_EQ(state.sample.force[1], -50.0f);
  EXPECT_EQ(state.extras.pressure.size(), 40u * 360u);
  EXPECT_TRUE(state.extras.assembly_space_known);
  ws.close(websocket::close_code::normal);
}

TEST_F(ServerTest, ForeignOriginIsRefused) {
  asio::io_context io;
  websocket::stream<tcp::socket> ws(io);
  ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
  ws.set_option(websocket::stream_base::decorator(
      [](websocket::request_type& r) { r.set(http::field::origin, "http://evil.example"); }));
  websocket::response_type response;
  EXPECT_THROW(ws.handshake(response, "127.0.0.1", "/ws"), beast::system_error);
  const std::string upgrade =
      "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
      "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n";
  EXPECT_EQ(Raw(upgrade + "Origin: http://evil.example\r\n\r\n").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(Raw(upgrade + "Origin: http://127.0.0.1:1\r\n\r\n").rfind("HTTP/1.1 403", 0), 0u);
  // The page's own origin is accepted: the raw handshake gets its 101.
  EXPECT_EQ(Raw(upgrade + "Origin: " + Origin() + "\r\n\r\n").rfind("HTTP/1.1 101", 0), 0u);
}

TEST_F(ServerTest, OversizedClientMessageClosesOnlyThatClient) {
  asio::io_context io;
  websocket::stream<tcp::socket> ws(io);
  ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
  ws.handshake("127.0.0.1", "/ws");
  ws.write(asio::buffer(std::string(4 * Server::kMaxClientMessage, 'x')));
  beast::flat_buffer buffer;
  beast::error_code ec;
  for (int i = 0; i < 1000 && !ec; ++i) {
    buffer.consume(buffer.size());
    ws.read(buffer, ec);
  }
  EXPECT_TRUE(ec);  // the server closed it
  EXPECT_EQ(Get("/").rfind("HTTP/1.1 200", 0), 0u);
}

TEST_F(ServerTest, ClientThatVanishesMidFrameCostsNothing) {
  for (int k = 0; k < 5; ++k) {
    asio::io_context io;
    websocket::stream<tcp::socket> ws(io);
    ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
    ws.handshake("127.0.0.1", "/ws");
    char some[100];
    ws.next_layer().read_some(asio::buffer(some));  // part of the scene, then gone
    ws.next_layer().close();
  }
  // The server notices each close on its own thread: wait for it, bounded only against a hang (a
  // minute, far beyond any machine's stall) since how soon that thread runs is not ours to assert.
  for (int i = 0; i < 6000 && server_->clients() > 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(server_->clients(), 0);
  EXPECT_EQ(Get("/").rfind("HTTP/1.1 200", 0), 0u);
}

// A several-feature scene: after the scene message, every feature's inner and outer mesh, in
// the scenario's order; the page's placement module is served beside the page.
TEST(Server, SendsEveryFeaturesMeshes) {
  PluginRegistry registry;
  registry.LoadAll();
  const ViewModel model(LoadScene("scenarios/keyed-hub.yaml", registry), 1);
  ASSERT_EQ(model.mesh_count(), 4);
  Server server(model, nullptr, {}, ServerOptions{});
  server.Start();
  asio::io_context io;
  websocket::stream<tcp::socket> ws(io);
  ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  ws.handshake("127.0.0.1", "/ws");
  beast::flat_buffer buffer;
  ws.read(buffer);
  EXPECT_TRUE(ws.got_text());
  EXPECT_NE(beast::buffers_to_string(buffer.data()).find("\"features\""), std::string::npos);
  for (int k = 0; k < 4; ++k) {
    buffer.consume(buffer.size());
    ws.read(buffer);
    EXPECT_TRUE(ws.got_binary());
    EXPECT_EQ(beast::buffers_to_string(buffer.data()), model.mesh_frame(k)) << k;
  }
  ws.close(websocket::close_code::normal);

  tcp::socket socket(io);
  socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  http::request<http::empty_body> get(http::verb::get, "/joint.js", 11);
  get.set(http::field::host, "127.0.0.1");
  http::write(socket, get);
  http::response<http::string_body> reply;
  beast::flat_buffer http_buffer;
  http::read(socket, http_buffer, reply);
  EXPECT_EQ(reply.result_int(), 200);
  EXPECT_NE(reply.body().find("export function bodyPose"), std::string::npos);
}

TEST(Server, RefusesAnAddressItCannotBind) {
  PluginRegistry registry;
  registry.LoadAll();
  const ViewModel model(LoadScene("scenarios/paper-case1-ve1.yaml", registry), 1);
  ServerOptions options;
  options.host = "not-an-address";
  Server bad(model, nullptr, {}, options);
  EXPECT_THROW(bad.Start(), UserError);
  options.host = "127.0.0.1";
  options.frame_rate = 0.0;
  EXPECT_THROW(Server(model, nullptr, {}, options), UserError);
}

}  // namespace
}  // namespace fitfeel::view
