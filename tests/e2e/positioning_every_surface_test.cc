// Positioning for every surface: each shipped scenario whose surface gives coarse meshes (the
// cylinder's own test is surfaces/cylindrical/test/coarse_mesh_scenario_test.cc) loads as
// `fitfeel run` loads it, and its positioning stage lets the centred part in, pushes an
// off-axis one back from the mating part's face before the constrained stage engages, pushes a
// part pressed sideways inside the mating part back towards the axis, and hands over to the
// constrained stage at the entrance.
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "framework/collision/coarse_mesh.h"
#include "framework/collision/mesh_collider.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/scenario/scene.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

struct SurfaceCase {
  std::string scenario;
  // Beyond the mating part's bore or slot at the entrance face: the leading end lands on the face.
  double off_axis = 0.0;  // m, along x
  // Inside the mating part, pressed sideways by more than the capture radius: into a wall.
  double inside_depth = 0.0;  // m
  double sideways = 0.0;      // m, along x
  // Where the mating part's entrance face is: a chamfer lies in front of the mating surface.
  double face = 0.0;  // m, along y
};

void PrintTo(const SurfaceCase& c, std::ostream* out) { *out << c.scenario; }

PartState At(double x, double y, double z) {
  PartState s;
  s.position = Eigen::Vector3d(x, y, z);
  return s;
}

class PositioningEverySurface : public ::testing::TestWithParam<SurfaceCase> {};

TEST_P(PositioningEverySurface, CollidesBeforeMatingAndHandsOverAtTheEntrance) {
  const SurfaceCase& c = GetParam();
  PluginRegistry registry({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"});
  registry.LoadAll();
  const Scene scene =
      LoadScene(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / c.scenario, registry);
  const CoarseMeshes meshes = scene.surface->MakeCoarseMeshes(scene.inner, scene.outer);
  ASSERT_FALSE(meshes.empty()) << c.scenario << ": the surface gives no coarse meshes";
  // Every shipped surface builds its meshes of convex solids: the collider's fast path.
  EXPECT_TRUE(MeshCollider(meshes.outer, meshes.inner).convex_pieces()) << c.scenario;

  constexpr double k = 1e3;  // N/m
  PositioningStage::Options options;
  options.free_stiffness = k;
  const PositioningStage stage(options, meshes, scene.moving);
  const std::unique_ptr<StageState> state = stage.MakeState();
  StageOutput out;

  // Centred, 1 mm before the entrance: free.
  stage.Evaluate(At(0.0, -1e-3, 0.0), state.get(), &out);
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(out.next, StageId::kPositioning);
  // Centred at the entrance: handed over, nothing rendered.
  stage.Evaluate(At(0.0, 0.0, 0.0), state.get(), &out);
  EXPECT_EQ(out.next, StageId::kConstrained);
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  // Off the axis, 0.2 mm through the entrance face: pushed straight back out, by the depth.
  stage.Evaluate(At(c.off_axis, c.face + 2e-4, 0.0), state.get(), &out);
  EXPECT_EQ(out.next, StageId::kPositioning);
  EXPECT_NEAR(out.wrench.force.y(), -k * 2e-4, k * 1e-6) << out.wrench.force.transpose();
  EXPECT_NEAR(out.wrench.force.x(), 0.0, k * 1e-6);
  // Inside, pressed sideways beyond the capture radius: pushed back towards the axis.
  stage.Evaluate(At(c.sideways, c.inside_depth, 0.0), state.get(), &out);
  EXPECT_EQ(out.next, StageId::kPositioning);
  EXPECT_LT(out.wrench.force.x(), -k * 0.5 * (c.sideways - options.capture_radius))
      << out.wrench.force.transpose();
}

INSTANTIATE_TEST_SUITE_P(
    Shipped, PositioningEverySurface,
    ::testing::Values(
        // 8 mm key in its keyway (flanks at +-4 mm): 6 mm off lands on the hub beside the slot;
        // 0.8 mm sideways 10 mm in presses a flank 0.8 mm into the wall.
        SurfaceCase{"key-parallel.yaml", 6e-3, 10e-3, 0.8e-3},
        // 20 mm square shaft in its square hole.
        SurfaceCase{"square-shaft.yaml", 14e-3, 10e-3, 0.8e-3},
        // 8 mm 1:50 taper pin, 20 mm hole (large end 8.4 mm): 7 mm off lands on the hub's face
        // (0.5 mm in front of the mating cone: the hole's C0.5 chamfer); 15 mm in the radial
        // clearance is (20 - 15) / 100 = 0.05 mm, so 0.8 mm sideways cuts the wall.
        SurfaceCase{"taper-pin.yaml", 7e-3, 15e-3, 0.8e-3, -0.5e-3}),
    [](const ::testing::TestParamInfo<SurfaceCase>& param) {
      std::string name = param.param.scenario.substr(0, param.param.scenario.find('.'));
      for (char& ch : name) {
        if (ch == '-') ch = '_';
      }
      return name;
    });

}  // namespace
}  // namespace fitfeel
