// Cost of one positioning-stage tick with coarse meshes (the paper pair's 20 mm fit: a 60 mm shaft
// prism and a 20 mm bushing tube with a 30 mm hub, 50 or 200 facets each), free and in contact:
// the end struck on the bushing's face, and a tilted part pressed into the bore's wall. The
// second argument 1 gives the bushing as one solid (not convex), which the collider takes to FCL;
// 0 as the convex sectors MakeTube builds (the shipped surfaces' meshes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "framework/collision/coarse_mesh.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/testing/solid_tube.h"

namespace fitfeel {
namespace {

PositioningStage MakeStage(int facets, bool fcl) {
  CoarseMeshes meshes;
  meshes.inner = MakeClosedCylinder(10e-3, -60e-3, 0.0, facets);
  meshes.outer = fcl ? test_support::SolidTube(10e-3, 15e-3, 0.0, 20e-3, facets)
                     : MakeTube(10e-3, 15e-3, 0.0, 20e-3, facets);
  PositioningStage::Options options;
  options.free_stiffness = 2e3;
  return PositioningStage(options, meshes, Role::kInner);
}

void Run(benchmark::State& state, const PartState& device) {
  const PositioningStage stage = MakeStage(static_cast<int>(state.range(0)), state.range(1) != 0);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  for (auto _ : state) {
    stage.Evaluate(device, stage_run.get(), &out);
    benchmark::DoNotOptimize(out.wrench.force.data());
  }
  state.counters["force_N"] = out.wrench.force.norm();
}

PartState At(double x, double y, double z, double tilt = 0.0) {
  PartState s;
  s.position = Eigen::Vector3d(x, y, z);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitZ()));
  return s;
}

void BM_PositioningTickFree(benchmark::State& state) { Run(state, At(3e-3, -2e-3, 0.0)); }
// Bounding volumes overlap (the shaft runs 50 um beside the hub's outside), no triangle pair does.
void BM_PositioningTickNearMiss(benchmark::State& state) { Run(state, At(25.05e-3, 5e-3, 0.0)); }
void BM_PositioningTickFaceContact(benchmark::State& state) { Run(state, At(3e-3, 0.1e-3, 0.0)); }
// 2 degrees of tilt (past the hand-over tolerance) 5 mm inside the bore: wall against wall.
void BM_PositioningTickTiltedInBore(benchmark::State& state) {
  Run(state, At(0.0, 5e-3, 0.0, 0.035));
}

BENCHMARK(BM_PositioningTickFree)->ArgsProduct({{50, 200}, {0, 1}});
BENCHMARK(BM_PositioningTickNearMiss)->ArgsProduct({{50, 200}, {0, 1}});
BENCHMARK(BM_PositioningTickFaceContact)->ArgsProduct({{50, 200}, {0, 1}});
BENCHMARK(BM_PositioningTickTiltedInBore)->ArgsProduct({{50, 200}, {0, 1}});

}  // namespace
}  // namespace fitfeel
