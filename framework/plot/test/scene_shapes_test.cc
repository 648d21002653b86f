#include "framework/plot/scene_shapes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plot/render.h"
#include "framework/plot/scene_charts.h"
#include "framework/plot/test/fake_surface.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

using ::testing::HasSubstr;
using testing::ScratchDir;

std::filesystem::path WriteScenario(const std::filesystem::path& dir, const std::string& law) {
  const auto file = dir / "scene.yaml";
  testing::WriteFile(file,
                     "scenario: plot-h7js6\n"
                     "surface: test.plot.cylinder\n"
                     "parts:\n"
                     "  shaft:\n"
                     "    role: inner\n"
                     "    size: 20 mm js6\n"
                     "    geometry: {length: 60 mm}\n"
                     "    material: {name: steel, youngs_modulus: 210 GPa, poisson: 0.3}\n"
                     "  bushing:\n"
                     "    role: outer\n"
                     "    size: 20 mm H7\n"
                     "    geometry: {length: 20 mm}\n"
                     "    material: {name: steel, youngs_modulus: 210 GPa, poisson: 0.3}\n"
                     "moving: shaft\n"
                     "model:\n"
                     "  law: " +
                         law +
                         "\n"
                         "  friction: 0.15\n"
                         "  contact_stiffness: 2 N/um\n"
                         "  resolution: {rows: 30, columns: 36}\n"
                         "device: {plugin: test.plot.device}\n"
                         "run: {duration: 1 s, seed: 7}\n");
  return file;
}

Scene Load(const std::filesystem::path& file) {
  PluginRegistry registry(std::vector<std::filesystem::path>{});
  testing::RegisterPlotFakes(registry);
  return LoadScene(file, registry);
}

TEST(GenerateSceneShapes, SameSeedSameShapesInnerDrawnFirst) {
  ScratchDir dir;
  const auto file = WriteScenario(dir.path(), "lame");
  const SceneShapes a = GenerateSceneShapes(Load(file));
  const SceneShapes b = GenerateSceneShapes(Load(file));
  EXPECT_EQ(a.seed, 7u);
  EXPECT_EQ(a.inner.grid.rows, 30);
  EXPECT_EQ(a.inner.variation, b.inner.variation);
  EXPECT_EQ(a.outer.variation, b.outer.variation);
  // The run's order: one generator from the seed, the inner part's draws first.
  Rng rng(7);
  std::uniform_real_distribution<double> shaft(-3.25e-6, 3.25e-6);
  EXPECT_DOUBLE_EQ(a.inner.variation(0), shaft(rng));
  const SceneShapes c = GenerateSceneShapes(Load(file), 8);
  EXPECT_NE(a.inner.variation, c.inner.variation);
}

TEST(ScenePipeline, SmsAndPressureChartsRender) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  const SceneShapes shapes = GenerateSceneShapes(Load(WriteScenario(dir.path(), "lame")));
  const Scene& scene = shapes.scene;
  Render(MakeSceneSmsChart(scene.name, scene.inner, shapes.inner, scene.outer, shapes.outer, true),
         ResolveOutputs(dir.path() / "sms"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "sms.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "sms.svg"));

  testing::WriteRun(dir.path() / "run", "plot-h7js6", "lame", 50.0);
  const PreparedContact contact = PrepareContact(shapes, "lame");
  const PressureMapData data = MakePressureData(LoadRun(dir.path() / "run"), 5.0, *contact.analyzer,
                                                *contact.law, shapes.inner.grid);
  EXPECT_GT(data.interference.maxCoeff(), 0.0);  // js6 in H7 can interfere
  Render(MakePressureChart(data), ResolveOutputs(dir.path() / "pressure.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "pressure.png"));
}

TEST(CheckSameGrids, RefusesShapesOfAChangedScenario) {
  ScratchDir dir;
  const SceneShapes shapes = GenerateSceneShapes(Load(WriteScenario(dir.path(), "lame")));
  EXPECT_NO_THROW(CheckSameGrids(shapes, std::make_pair(30, 36), std::make_pair(30, 36)));
  EXPECT_NO_THROW(CheckSameGrids(shapes, std::nullopt, std::nullopt));
  try {
    CheckSameGrids(shapes, std::make_pair(40, 36), std::nullopt);
    FAIL() << "a changed grid was accepted";
  } catch (const UserError& e) {
    EXPECT_THAT(e.what(), HasSubstr("30 x 36 cells, the run had 40 x 36"));
  }
}

TEST(PrepareContact, LawWithoutPressureModelIsRefusedClearly) {
  ScratchDir dir;
  const SceneShapes shapes = GenerateSceneShapes(Load(WriteScenario(dir.path(), "ideal")));
  const PreparedContact contact = PrepareContact(shapes);
  try {
    contact.law->PressurePerInterference();
    FAIL() << "a law without a pressure model gave a coefficient";
  } catch (const UnsupportedError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no contact pressure"));
  }
}

}  // namespace
}  // namespace fitfeel::plot
