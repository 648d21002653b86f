// The paper's H7/g6 scenario, loaded through the plugin registry as `fitfeel run` loads it: the
// cylindrical plugin's coarse meshes reach the positioning stage, which lets the centred shaft in
// and pushes an off-axis one back from the bushing's face.
#include <filesystem>
#include <memory>
#include <string>

#include "framework/collision/coarse_mesh.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/scenario/scene.h"
#include "framework/testing/source_tree.h"

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using test_support::ShippedScenario;

namespace fs = std::filesystem;

PartState DeviceAt(double x, double y, double z) {
  PartState s;
  s.position = Eigen::Vector3d(x, y, z);
  return s;
}

TEST(CylindricalCoarseMeshScenario, ThePluginsMeshesReachThePositioningStage) {
  PluginRegistry registry({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"});
  registry.LoadAll();
  const Scene scene = LoadScene(ShippedScenario("paper-case1-h7g6.yaml"), registry);
  const CoarseMeshes meshes = scene.surface->MakeCoarseMeshes(scene.inner, scene.outer);
  ASSERT_FALSE(meshes.empty());
  // H7/g6 at 20 mm: 54 facets (see cylindrical_coarse_mesh.h): a 40 mm prism and the frustum
  // of its C0.5 end; a tube and the tapered tube of its C1 entrance, each a convex sector per
  // facet (so the collider takes convex pieces).
  EXPECT_EQ(meshes.inner.triangles.size(), 8u * 54);
  EXPECT_EQ(meshes.outer.triangles.size(), 24u * 54);

  PositioningStage::Options options;
  options.free_stiffness = 1e3;
  const PositioningStage stage(options, meshes, scene.moving);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  ASSERT_TRUE(stage.collides());
  StageOutput out;
  stage.Evaluate(DeviceAt(0.0, -1e-3, 0.0), stage_run.get(), &out);
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  stage.Evaluate(DeviceAt(0.0, 0.0, 0.0), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kConstrained);
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  // 4 mm off, 0.2 mm past the face (y = -1 mm, in front of the C1 entrance): the end lands on it.
  stage.Evaluate(DeviceAt(0.0, -0.8e-3, 4e-3), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kPositioning);
  EXPECT_NEAR(out.wrench.force.y(), -1e3 * 2e-4, 1e-9);
}

}  // namespace
}  // namespace fitfeel
