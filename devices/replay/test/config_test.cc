#include <fstream>

#include <gtest/gtest.h>

#include "devices/replay/replay_device.h"
#include "framework/core/error.h"

namespace fitfeel::replay {
namespace {

namespace fs = std::filesystem;

TEST(ReplayConfig, ParsesKeysAndResolvesTheFileBesideTheScenario) {
  const fs::path dir = fs::temp_directory_path() / "fitfeel_replay_config_test";
  fs::create_directories(dir);
  std::vector<RecordedSample> samples(3);
  for (int i = 0; i < 3; ++i) samples[i].time = i * 1e-3;
  WriteRecording(dir / "hand.rec", {"Touch"}, samples);
  const std::string scene = (dir / "scene.yaml").string();
  ReplayDevice device;
  device.Configure(
      ConfigNode::Parse("{plugin: fitfeel.device.replay, file: hand.rec, speed: 0.5, start: 1 ms,"
                        " loop: true, spec: {max_force: 2 N}}",
                        scene, "device"));
  EXPECT_EQ(device.spec().model, "Touch");
  EXPECT_DOUBLE_EQ(device.spec().max_force, 2.0);
  EXPECT_THROW(device.Configure(ConfigNode::Parse("{file: nope.rec}", scene, "device")),
               ScenarioError);
  EXPECT_THROW(
      device.Configure(ConfigNode::Parse("{file: hand.rec, speed: -1}", scene, "device")),
      ScenarioError);
  EXPECT_THROW(
      device.Configure(ConfigNode::Parse("{file: hand.rec, colour: red}", scene, "device")),
      ScenarioError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fitfeel::replay
