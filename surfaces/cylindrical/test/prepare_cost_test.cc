// The elastic law's own prepare estimate (elastic_cost.h) and the loader's admission with it: a
// press fit with four times the rows costs about 20 times the prepare, which the per-cell
// estimate alone (10 us a cell) does not see.
#include <cmath>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/config_node.h"
#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/testing/source_tree.h"
#include "surfaces/cylindrical/cylindrical_options.h"
#include "surfaces/cylindrical/cylindrical_surface.h"
#include "surfaces/cylindrical/elastic_cost.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

namespace fitfeel::cylindrical {
namespace {

namespace fs = std::filesystem;

ModelSettings ElasticWith(const std::string& options = "{}") {
  ModelSettings model;
  model.law = "elastic";
  model.options = testing::ParsedOptions(options, "scene.yaml");
  return model;
}

TEST(ElasticPrepareCost, GrowsWithTheRowsCubedTheOrdersAndTheColumns) {
  const CylindricalSurface surface;
  const GridShape grid{40, 360};
  // fits-20mm-h7n6: 120 depth steps at 40 rows, 6 orders, 120 solve columns.
  const double base = surface.EstimatePrepareSeconds(ElasticWith(), grid, grid, 120.0);
  EXPECT_DOUBLE_EQ(base, kElasticSecondsPerRowStep * 120 * 40 * 40 * 7);
  // Twice the rows: twice the depth steps, four times the row pairs.
  EXPECT_DOUBLE_EQ(surface.EstimatePrepareSeconds(ElasticWith(), {80, 360}, {80, 360}, 240.0),
                   8.0 * base);
  EXPECT_DOUBLE_EQ(
      surface.EstimatePrepareSeconds(ElasticWith("{axial_orders: 0}"), grid, grid, 120.0),
      base / 7.0);
  EXPECT_DOUBLE_EQ(
      surface.EstimatePrepareSeconds(ElasticWith("{axial_coupling: false}"), grid, grid, 120.0),
      base / 7.0);
  EXPECT_DOUBLE_EQ(surface.EstimatePrepareSeconds(ElasticWith("{columns: 480}"), grid, grid, 120.0),
                   base * std::sqrt(3.0));  // the grid's 360 columns, not the option's 480
  EXPECT_DOUBLE_EQ(surface.EstimatePrepareSeconds(ElasticWith("{columns: 30}"), grid, grid, 120.0),
                   base * 0.5);
  // The paper's laws prepare in proportion to the cells: nothing of their own.
  ModelSettings gps = ElasticWith();
  gps.law = "gps";
  EXPECT_EQ(surface.EstimatePrepareSeconds(gps, grid, grid, 120.0), 0.0);
  EXPECT_THROW(surface.EstimatePrepareSeconds(ElasticWith(), grid, grid, -1.0), UserError);
  EXPECT_THROW(surface.EstimatePrepareSeconds(ElasticWith(), {-1, 360}, grid, 1.0), UserError);
}

// fits-20mm-h7n6 as shipped is admitted; at 160 rows (480 depth steps) its worst case is 69 s
// (measured: 100 s of CPU) and it is refused at model.resolution, saying how much of the estimate
// is the law's own, unless large scenes are allowed.
TEST(ElasticPrepareCost, AFinePressFitIsRefusedAtItsResolution) {
  PluginRegistry registry({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"});
  registry.LoadAll();
  const fs::path shipped = test_support::ShippedScenario("fits-20mm-h7n6.yaml");
  const Scene scene = LoadScene(shipped, registry);
  EXPECT_NEAR(scene.cost.prepare_seconds, 0.288 + kElasticSecondsPerRowStep * 120 * 1600 * 7, 0.01);
  std::stringstream text;
  text << std::ifstream(shipped).rdbuf();
  std::string fine = text.str();
  const std::string grid = "resolution: {rows: 40, columns: 360}";
  ASSERT_NE(fine.find(grid), std::string::npos);
  fine.replace(fine.find(grid), grid.size(), "resolution: {rows: 160, columns: 360}");
  const fs::path file = fs::path(::testing::TempDir()) / "fitfeel_fine_press_fit.yaml";
  std::ofstream(file) << fine;
  try {
    LoadScene(file, registry);
    ADD_FAILURE() << "admitted";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "model.resolution");
    EXPECT_NE(e.found().find("s of it the law's own, at worst"), std::string::npos) << e.what();
  }
  LoadOptions large;
  large.allow_large = true;
  const Scene allowed = LoadScene(file, registry, large);
  EXPECT_GT(allowed.cost.prepare_seconds, kLargeSceneSeconds);
}

}  // namespace
}  // namespace fitfeel::cylindrical
