// A sequence on the viewer (SequenceView, Server's steps): the steps announced in order, each with
// its scene message and meshes before any of its state, a finished step asked for again, and the
// run the viewer watches the one `fitfeel run` runs.
#include "framework/view/sequence_view.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include "framework/plugin/registry.h"
#include "framework/runtime/sequence_run.h"
#include "framework/scenario/sequence.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/view/frame_codec.h"

namespace fitfeel::view {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace fs = std::filesystem;
using tcp = asio::ip::tcp;

// One message of the server, as a client reads it.
struct StepMessage {
  bool text = false;
  std::string body;
  nlohmann::json json;     // of a text message
  std::uint16_t kind = 0;  // of a binary frame: FrameKind
};

class StepClient {
 public:
  explicit StepClient(unsigned short port) : ws_(io_) {
    ws_.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    ws_.handshake("127.0.0.1", "/ws");
  }
  StepMessage Read() {
    beast::flat_buffer buffer;
    ws_.read(buffer);
    StepMessage m;
    m.text = ws_.got_text();
    m.body = beast::buffers_to_string(buffer.data());
    if (m.text) {
      m.json = nlohmann::json::parse(m.body);
    } else if (m.body.size() >= kHeaderBytes) {
      m.kind = static_cast<std::uint16_t>(static_cast<unsigned char>(m.body[6]) |
                                          static_cast<unsigned char>(m.body[7]) << 8);
    }
    return m;
  }
  void Send(const std::string& text) {
    ws_.text(true);
    ws_.write(asio::buffer(text));
  }
  ~StepClient() {
    beast::error_code ignored;
    ws_.close(websocket::close_code::normal, ignored);
  }

 private:
  asio::io_context io_;
  websocket::stream<tcp::socket> ws_;
};

bool IsSequence(const StepMessage& m) { return m.text && m.json.value("type", "") == "sequence"; }
bool IsScene(const StepMessage& m) { return m.text && m.json.value("type", "") == "scene"; }

// The rows of a trace.csv without its tick_us column (the tick's compute time, which no two runs
// share).
std::vector<std::string> TraceWithoutTickTimes(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  std::string line;
  int tick_us = -1;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cells_in(line);
    for (std::string cell; std::getline(cells_in, cell, ',');) cells.push_back(cell);
    if (tick_us < 0) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] == "tick_us") tick_us = static_cast<int>(i);
      }
    }
    if (tick_us >= 0 && tick_us < static_cast<int>(cells.size())) {
      cells.erase(cells.begin() + tick_us);
    }
    std::string row;
    for (const std::string& cell : cells) row += cell + ",";
    rows.push_back(row);
  }
  return rows;
}

TEST(SequenceView, AnnouncesTheStepsInOrderWithTheirScenes) {
  const Sequence sequence =
      LoadSequence("scenarios/key-then-hub.yaml", test_support::BuildTreePlugins());
  ASSERT_EQ(sequence.steps.size(), 2u);
  const fs::path dir = fs::path(::testing::TempDir()) / "fitfeel_sequence_view_test";
  fs::remove_all(dir);
  SequenceView view(sequence, 1, ServerOptions{});
  view.server().Start();
  StepClient client(view.server().port());

  // Before the run: the sequence with no step begun, then step 0's scene and its two meshes.
  const StepMessage first = client.Read();
  ASSERT_TRUE(IsSequence(first)) << first.body.substr(0, 200);
  EXPECT_EQ(first.json["scenario"], "key-then-hub");
  EXPECT_EQ(first.json["newest"], 0);
  ASSERT_EQ(first.json["steps"].size(), 2u);
  EXPECT_EQ(first.json["steps"][0]["step"], "key");
  EXPECT_EQ(first.json["steps"][1]["step"], "hub");
  EXPECT_EQ(first.json["steps"][1]["seed"], 2);  // the sequence's seed plus the step's index
  EXPECT_FALSE(first.json["steps"][0]["finished"].get<bool>());
  const StepMessage key_scene = client.Read();
  ASSERT_TRUE(IsScene(key_scene));
  EXPECT_EQ(key_scene.json["scenario"], "key");
  EXPECT_EQ(key_scene.json["step"], 0);
  EXPECT_EQ(key_scene.json["seed"], 1);
  EXPECT_EQ(key_scene.body, view.model(0).scene_message());
  for (int k = 0; k < 2; ++k) EXPECT_EQ(client.Read().body, view.model(0).mesh_frame(k)) << k;

  RunOptions options;
  options.clock = ClockMode::kVirtual;
  options.out_dir = dir / "viewed";
  const SequenceResult viewed = RunSequence(sequence, options, view.Watch());
  ASSERT_EQ(view.steps(), 2u);

  // Everything that came during the run, up to the sequence message with both steps finished.
  std::vector<StepMessage> log;
  for (;;) {
    log.push_back(client.Read());
    const StepMessage& m = log.back();
    if (IsSequence(m) && m.json["steps"][1]["finished"].get<bool>()) break;
  }
  // Step 0 finishes, then step 1 begins: the sequence says so, then step 1's scene message and
  // its four meshes, in order, with nothing of step 0 after them.
  std::size_t key_done = log.size(), hub_begun = log.size(), hub_scene = log.size();
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (IsSequence(log[i]) && key_done == log.size() && log[i].json["steps"][0]["finished"]) {
      key_done = i;
    }
    if (IsSequence(log[i]) && log[i].json["newest"] == 1 && hub_begun == log.size()) hub_begun = i;
    if (IsScene(log[i])) {
      EXPECT_EQ(hub_scene, log.size()) << "a second scene message at " << i;
      hub_scene = i;
    }
  }
  ASSERT_LT(key_done, log.size());
  ASSERT_LT(hub_begun, log.size());
  EXPECT_LT(key_done, hub_begun);
  ASSERT_EQ(hub_scene, hub_begun + 1);
  const StepMessage& hub = log[hub_scene];
  EXPECT_EQ(hub.json["scenario"], "hub");
  EXPECT_EQ(hub.json["step"], 1);
  EXPECT_EQ(hub.json["seed"], 2);
  EXPECT_EQ(hub.body, view.model(1).scene_message());
  ASSERT_EQ(view.model(1).mesh_count(), 4);
  ASSERT_LT(hub_scene + 4, log.size());
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(log[hub_scene + 1 + k].body, view.model(1).mesh_frame(k)) << k;
  }
  // The state frames on either side of the switch are their step's: the key's pressure map has
  // its 4 x 32 cells, the bore's its 48 x 72.
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (log[i].text || log[i].kind != static_cast<std::uint16_t>(FrameKind::kState)) continue;
    const std::size_t cells = DecodeStateFrame(log[i].body).extras.pressure.size();
    if (cells == 0) continue;
    EXPECT_EQ(cells, i < hub_scene ? 4u * 32u : 48u * 72u) << "state frame " << i;
  }
  // What each finished step left is its entry of the sequence's summary.json.
  const nlohmann::json& last = log.back().json;
  EXPECT_EQ(last["newest"], 1);
  for (std::size_t k = 0; k < 2; ++k) {
    nlohmann::json entry = last["steps"][k];
    EXPECT_TRUE(entry["finished"].get<bool>());
    entry.erase("finished");
    EXPECT_EQ(entry, viewed.summary_json["steps"][k]) << k;
  }
  // The seated key is drawn where step 0 left it, across its flanks (`carry: x`).
  const double seat = viewed.steps[0].final_pose.offset.x();
  ASSERT_NE(seat, 0.0);
  const nlohmann::json& key_feature = hub.json["features"][1];
  EXPECT_EQ(key_feature["name"], "key");
  EXPECT_EQ(key_feature["inner"]["seat_um"], nlohmann::json({seat * 1e6, 0.0}));
  EXPECT_FALSE(key_feature["outer"].contains("seat_um"));  // the hub's keyway moves

  // A finished step asked for again: its scene message and meshes, then its own states.
  client.Send("step 0");
  StepMessage again = client.Read();
  while (!IsScene(again)) again = client.Read();  // states of step 1 sent before the answer
  EXPECT_EQ(again.body, view.model(0).scene_message());
  for (int k = 0; k < 2; ++k) EXPECT_EQ(client.Read().body, view.model(0).mesh_frame(k)) << k;

  // The viewer watched the run `fitfeel run` runs: the same summary and the same traces.
  options.out_dir = dir / "run";
  const SequenceResult run = RunSequence(sequence, options);
  EXPECT_EQ(run.summary_json, viewed.summary_json);
  for (const char* step : {"key", "hub"}) {
    const std::vector<std::string> a = TraceWithoutTickTimes(dir / "viewed" / step / "trace.csv");
    EXPECT_GT(a.size(), 500u) << step;
    EXPECT_EQ(a, TraceWithoutTickTimes(dir / "run" / step / "trace.csv")) << step;
  }
  fs::remove_all(dir);
}

// A finished sequence (every step with its history, as `fitfeel view --trace` serves it): a client
// starts on the last step; a scene's server takes no `step` request.
TEST(SequenceView, AFinishedSequenceOpensOnItsLastStep) {
  const Sequence sequence =
      LoadSequence("scenarios/key-then-hub.yaml", test_support::BuildTreePlugins());
  std::vector<std::shared_ptr<const ViewModel>> models;
  std::vector<ServedStep> steps(2);
  for (std::size_t k = 0; k < 2; ++k) {
    const Scene scene = StepScene(sequence, k, 1, {Eigen::Vector2d(0.25e-6, 0.0)});
    models.push_back(std::make_shared<const ViewModel>(scene, scene.run.seed, static_cast<int>(k)));
    steps[k].model = models.back();
    ViewSample row;
    row.time = 0.5 + static_cast<double>(k);
    steps[k].history = {row};
  }
  const std::vector<nlohmann::json> finished(2, nlohmann::json::object());
  Server server(std::move(steps), SequenceMessage(sequence, 1, 1, finished), ServerOptions{});
  server.Start();
  StepClient client(server.port());
  const StepMessage first = client.Read();
  ASSERT_TRUE(IsSequence(first));
  EXPECT_TRUE(first.json["steps"][0]["finished"].get<bool>());
  const StepMessage scene = client.Read();
  EXPECT_EQ(scene.body, models[1]->scene_message());
  for (int k = 0; k < 4; ++k) EXPECT_EQ(client.Read().body, models[1]->mesh_frame(k));
  EXPECT_EQ(client.Read().kind, static_cast<std::uint16_t>(FrameKind::kHistory));
  EXPECT_EQ(DecodeStateFrame(client.Read().body).sample.time, 1.5);
  // Out of range: ignored; step 0: its scene, meshes, history and state.
  client.Send("step 7");
  client.Send("step 0");
  EXPECT_EQ(client.Read().body, models[0]->scene_message());
  for (int k = 0; k < 2; ++k) EXPECT_EQ(client.Read().body, models[0]->mesh_frame(k));
  EXPECT_EQ(client.Read().kind, static_cast<std::uint16_t>(FrameKind::kHistory));
  EXPECT_EQ(DecodeStateFrame(client.Read().body).sample.time, 0.5);

  // A scene's server: `step 0` is not a request it knows; a seek is still answered.
  Server scene_server(*models[0], nullptr, {ViewSample{}}, ServerOptions{});
  scene_server.Start();
  StepClient scene_client(scene_server.port());
  EXPECT_EQ(scene_client.Read().body, models[0]->scene_message());
  for (int k = 0; k < 3; ++k) scene_client.Read();  // two meshes and the history
  EXPECT_EQ(scene_client.Read().kind, static_cast<std::uint16_t>(FrameKind::kState));
  scene_client.Send("step 0");
  scene_client.Send("seek 0");
  EXPECT_EQ(scene_client.Read().kind, static_cast<std::uint16_t>(FrameKind::kState));
}

}  // namespace
}  // namespace fitfeel::view
