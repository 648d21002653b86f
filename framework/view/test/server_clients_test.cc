// Many viewer clients on one server, on 127.0.0.1: the frames every client is sent are the
// server's shared buffers (200 clients that read nothing grow the process by a small fraction of
// a copy of the meshes each), and the client over the cap is answered 503 with a text body and
// said once on the server's log.
#include <malloc.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/view/server.h"
#include "framework/view/view_model.h"

namespace fitfeel::view {
namespace {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

// This process's resident set, KiB (/proc/self/status), after handing freed heap back to the
// system so that growth shows as growth.
long ResidentKib() {
  malloc_trim(0);
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// A client that upgrades to the WebSocket and then reads nothing more: the slowest reader.
struct Client {
  std::unique_ptr<tcp::socket> socket;
  std::string response;  // the head, and for a 503 its body
};

class ManyClients : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    registry_ = new PluginRegistry();
    registry_->LoadAll();
    model_ = new ViewModel(LoadScene("scenarios/paper-case1-h7js6.yaml", *registry_), 1);
  }
  static void TearDownTestSuite() {
    delete model_;
    delete registry_;
  }

  // Sends the upgrade and reads the response's head; after a 101, also the first byte of the
  // scene message, which the server queues with both meshes: they are then waiting for this
  // client. A refusal is read to its end (the server closes it).
  Client Connect(unsigned short port) {
    Client client;
    client.socket = std::make_unique<tcp::socket>(io_);
    client.socket->connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    const std::string upgrade =
        "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n";
    asio::write(*client.socket, asio::buffer(upgrade));
    std::string& got = client.response;
    char chunk[512];
    boost::system::error_code ec;
    for (;;) {
      const std::size_t head = got.find("\r\n\r\n");
      const bool upgraded = got.rfind("HTTP/1.1 101", 0) == 0;
      if (head != std::string::npos && upgraded && got.size() > head + 4) break;
      // One byte at a time after the head: the meshes stay in the server's hands.
      const std::size_t want = head == std::string::npos ? 1 : sizeof chunk;
      const std::size_t n = client.socket->read_some(asio::buffer(chunk, want), ec);
      got.append(chunk, n);
      if (ec) break;
    }
    return client;
  }

  // Polls the server's count of clients (it drops one when its socket is found closed); false if
  // it is not `n` within a generous bound.
  static bool WaitForClients(const Server& server, int n) {
    for (int i = 0; i < 6000 && server.clients() != n; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return server.clients() == n;
  }

  static PluginRegistry* registry_;
  static ViewModel* model_;
  asio::io_context io_;
};
PluginRegistry* ManyClients::registry_ = nullptr;
ViewModel* ManyClients::model_ = nullptr;

TEST_F(ManyClients, TwoHundredClientsShareTheFramesTheyAreSent) {
  const double frames = static_cast<double>(model_->mesh_frame(0).size() +
                                            model_->mesh_frame(1).size());
  ASSERT_GT(frames, 1e6) << "the meshes are small enough to hide copies";
  ServerOptions options;
  options.max_clients = 200;
  Server server(*model_, nullptr, {}, options);
  server.Start();
  const long before = ResidentKib();
  std::vector<Client> clients;
  for (int k = 0; k < 200; ++k) {
    clients.push_back(Connect(server.port()));
    ASSERT_EQ(clients.back().response.rfind("HTTP/1.1 101", 0), 0u)
        << "client " << k << ": " << clients.back().response.substr(0, 80);
  }
  ASSERT_TRUE(WaitForClients(server, 200)) << server.clients() << " clients, not 200";
  const long after = ResidentKib();
  ASSERT_GT(before, 0);
  // A copy of both meshes per client would be 200 x 1.8 MB; shared, each client costs its socket
  // and session: a tenth of the copies is a bound no copying server meets.
  const double growth = static_cast<double>(after - before) * 1024.0;
  EXPECT_LT(growth, 200.0 * frames / 10.0)
      << "resident set grew by " << growth / 1e6 << " MB for 200 clients; a copy of the meshes "
      << "each is " << 200.0 * frames / 1e6 << " MB";
  std::printf("[ measured ] 200 viewer clients: resident set %ld -> %ld MiB (+%.2f MB, %.1f kB "
              "a client; the meshes are %.2f MB)\n",
              before / 1024, after / 1024, growth / 1e6, growth / 200.0 / 1e3, frames / 1e6);
  // The cap holds: one more is refused.
  EXPECT_EQ(Connect(server.port()).response.rfind("HTTP/1.1 503", 0), 0u);
  EXPECT_EQ(server.clients(), 200);
  clients.clear();
  EXPECT_TRUE(WaitForClients(server, 0)) << server.clients() << " clients left after closing all";
}

TEST_F(ManyClients, TheClientsOverTheDefaultCapAreAnswered503AndSaidOnce) {
  std::mutex mutex;
  std::vector<std::string> lines;
  ServerOptions options;
  ASSERT_EQ(options.max_clients, 64);
  options.log = [&](const std::string& line) {
    std::lock_guard<std::mutex> lock(mutex);
    lines.push_back(line);
  };
  Server server(*model_, nullptr, {}, options);
  server.Start();
  std::vector<Client> served;
  for (int k = 0; k < 200; ++k) {
    Client client = Connect(server.port());
    if (k < 64) {
      ASSERT_EQ(client.response.rfind("HTTP/1.1 101", 0), 0u) << k << ": " << client.response;
      served.push_back(std::move(client));
      continue;
    }
    ASSERT_EQ(client.response.rfind("HTTP/1.1 503", 0), 0u) << k << ": " << client.response;
    EXPECT_NE(client.response.find("Content-Type: text/plain"), std::string::npos);
    EXPECT_NE(client.response.find("\r\n\r\nthis viewer serves no more clients at once "
                                   "(--max-clients); close another viewer page and reload\n"),
              std::string::npos)
        << client.response;
  }
  EXPECT_EQ(server.clients(), 64);
  EXPECT_EQ(server.clients_refused(), 136u);
  {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_EQ(lines.size(), 1u) << "said once, not per refusal";
    EXPECT_EQ(lines[0].rfind("fitfeel view: 64 viewer clients connected, the most served at once "
                             "(--max-clients): refusing 127.0.0.1:",
                             0),
              0u)
        << lines[0];
  }
  // One leaves: the next is served, and a refusal after it is said again.
  served.pop_back();
  ASSERT_TRUE(WaitForClients(server, 63)) << server.clients() << " clients, not 63";
  served.push_back(Connect(server.port()));
  EXPECT_EQ(served.back().response.rfind("HTTP/1.1 101", 0), 0u) << served.back().response;
  EXPECT_EQ(Connect(server.port()).response.rfind("HTTP/1.1 503", 0), 0u);
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(lines.size(), 2u);
  }
  served.clear();
  EXPECT_TRUE(WaitForClients(server, 0)) << server.clients() << " clients left after closing all";
}

TEST_F(ManyClients, ACapOutsideItsRangeIsRefused) {
  ServerOptions options;
  for (int cap : {0, -1, Server::kMaxClientsCap + 1}) {
    options.max_clients = cap;
    EXPECT_THROW(Server(*model_, nullptr, {}, options), UserError) << cap;
  }
  options.max_clients = Server::kMaxClientsCap;
  EXPECT_NO_THROW(Server(*model_, nullptr, {}, options));
}

}  // namespace
}  // namespace fitfeel::view
