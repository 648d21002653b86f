// Through the registry, as `fitfeel run` and `fitfeel validate` load it: a thread scene is refused
// with the stub's limitation unless the caller only inspects skin model shapes.
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"

namespace fitfeel::thread {
namespace {

constexpr const char* kScenario = "surfaces/thread/test/conformance.yaml";

TEST(ThreadRefusalTest, LoadingARunnableSceneIsRefusedWithTheLimitation) {
  PluginRegistry registry;
  registry.LoadAll();
  try {
    LoadScene(kScenario, registry);
    FAIL() << "a thread scene was accepted for running";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "surface");
    EXPECT_NE(std::string(e.what()).find("has no resistance law yet"), std::string::npos)
        << e.what();
  }
}

TEST(ThreadRefusalTest, InspectionLoadsTheSceneButNoLawOrAnalyzer) {
  PluginRegistry registry;
  registry.LoadAll();
  LoadOptions options;
  options.allow_non_rendering = true;
  const Scene scene = LoadScene(kScenario, registry, options);
  ASSERT_NE(scene.surface, nullptr);
  EXPECT_FALSE(scene.surface->renders_forces());
  EXPECT_THROW(scene.surface->MakeContactAnalyzer(), UnsupportedError);
  EXPECT_NE(scene.inner.geometry, nullptr);
}

}  // namespace
}  // namespace fitfeel::thread
