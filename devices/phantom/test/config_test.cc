#include <gtest/gtest.h>

#include "devices/phantom/phantom_device.h"
#include "framework/core/error.h"

namespace fitfeel::phantom {
namespace {

ConfigNode Node(const std::string& text) {
  return ConfigNode::Parse(text, "scene.yaml", "device");
}

TEST(PhantomConfig, ModelAndSpecOverrides) {
  PhantomDevice device;
  device.Configure(
      Node("{plugin: fitfeel.device.phantom, model: touch, spec: {max_force: 2 N},"
           " auto_calibrate: false}"));
  EXPECT_EQ(device.spec().model, "Touch");
  EXPECT_DOUBLE_EQ(device.spec().max_force, 2.0);
  EXPECT_DOUBLE_EQ(device.spec().max_stiffness, 400.0);
}

TEST(PhantomConfig, RefusesUnknownKeysAndModels) {
  PhantomDevice device;
  EXPECT_THROW(device.Configure(Node("{model: falcon}")), ScenarioError);
  EXPECT_THROW(device.Configure(Node("{rate: 1 kHz}")), ScenarioError);
  EXPECT_THROW(device.Configure(Node("{spec: {max_force: 2 N}}")), ScenarioError);  // incomplete
}

}  // namespace
}  // namespace fitfeel::phantom
