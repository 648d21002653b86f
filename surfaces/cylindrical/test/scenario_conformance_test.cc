// Over 100 seeds, every generated skin model shape of the three paper
// scenarios meets every tolerance it came from. The scenarios are loaded through the plugin
// registry, unchanged, as `fitfeel run` loads them.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/testing/source_tree.h"

namespace fitfeel {
namespace {

using test_support::ShippedScenario;

namespace fs = std::filesystem;

// One test per scenario: each takes seconds, and ctest runs them side by side.
class CylindricalScenarioConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(CylindricalScenarioConformance, MeetsItsTolerancesOverAHundredSeeds) {
  PluginRegistry registry({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"});
  registry.LoadAll();
  const std::string scenario = GetParam() + ".yaml";
  const Scene scene = LoadScene(ShippedScenario(scenario), registry);
  ASSERT_EQ(scene.surface_id, "fitfeel.surface.cylindrical");
  const auto discretizer = scene.surface->MakeDiscretizer();
  const auto generator = scene.surface->MakeVariationGenerator();
  if (scene.model.options) generator->Configure(*scene.model.options);
  const SurfaceGrid inner_grid = discretizer->Discretize(scene.inner, scene.model.resolution);
  const SurfaceGrid outer_grid = discretizer->Discretize(scene.outer, scene.model.resolution);
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    Rng rng(seed);  // as the runtime draws them: inner, then outer
    const SkinModelShape inner =
        generator->Generate(scene.inner, inner_grid, scene.model.texture, rng);
    const SkinModelShape outer =
        generator->Generate(scene.outer, outer_grid, scene.model.texture, rng);
    for (const auto& [part, sms] : {std::pair{&scene.inner, &inner}, {&scene.outer, &outer}}) {
      const auto checks = scene.surface->EvaluateCharacteristics(*part, *sms);
      ASSERT_GE(checks.size(), 2u);
      for (const CharacteristicCheck& c : checks) {
        ++checked;
        EXPECT_GE(c.value, c.lower - 1e-12)
            << scenario << " seed " << seed << " " << part->name << " " << c.name;
        EXPECT_LE(c.value, c.upper + 1e-12)
            << scenario << " seed " << seed << " " << part->name << " " << c.name;
      }
    }
  }
  EXPECT_GE(checked, 100 * 2 * 4) << scenario;
}

INSTANTIATE_TEST_SUITE_P(Paper, CylindricalScenarioConformance,
                         ::testing::Values("paper-case1-h7js6", "paper-case1-h7g6",
                                           "paper-case1-ve1"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

}  // namespace
}  // namespace fitfeel
