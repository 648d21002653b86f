// The tick path must not allocate: this binary counts every heap allocation and runs the analyzer's
// and the laws' Evaluate over many poses.
#include <atomic>
#include <cstdlib>
#include <random>

#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "surfaces/cylindrical/cylindrical_coarse_mesh.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "framework/testing/allocation_counter.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Eigen allocates with malloc, not operator new, and libstdc++'s operator new calls malloc: so
// count at malloc itself, interposed over glibc's (the executable's definition wins).
#if FITFEEL_ALLOCATION_COUNTING
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* malloc(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
}
#endif

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

TEST(ContactTick, EvaluateDoesNotAllocateAndIsIndependentOfRows) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  const TextureSpec t{3.2 * kUm, 0.4 * kUm, 1.6 * kUm};
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  shaft.texture = t;
  bushing.texture = t;
  const int n = 48;
  for (int rows : {10, 400}) {
    std::mt19937_64 rng(rows);
    std::uniform_real_distribution<double> v(-6 * kUm, 6 * kUm);
    // Random form: mixes clearance and interference depths.
    Eigen::VectorXd vs(rows * n), vb(rows / 2 * n);
    for (auto& x : vs) x = v(rng);
    for (auto& x : vb) x = v(rng) + 4 * kUm;
    CylinderContactAnalyzer a;
    a.Prepare(
        shaft,
        MakeSms(MakeGrid(rows, n, 0.020, 0.040), [&](int i, int j) { return vs[i * n + j]; }),
        bushing,
        MakeSms(MakeGrid(rows / 2, n, 0.020, 0.020), [&](int i, int j) { return vb[i * n + j]; }),
        Settings(0.15, 0.0, TextureMode::kExpected));
    // By construction a tick touches one or two tabulated polygons of at most n + 4 vertices and a
    // fixed number of scalars per depth step: nothing proportional to the row count.
    EXPECT_LE(a.max_polygon_vertices(), n + 4);
    GpsLaw gps;
    gps.Prepare(shaft, bushing, Settings(0.15));
    Ve1Law ve1;
    ve1.Prepare(shaft, bushing, Settings(0.15, 1e7));
    std::uniform_real_distribution<double> depth(-5e-3, 65e-3), off(-20 * kUm, 20 * kUm);
    std::vector<MatingPose> poses(2000);
    for (auto& p : poses) {
      p.depth = depth(rng);
      p.offset = {off(rng), off(rng)};
    }
    int interfering = 0;
    const long before = g_allocations.load();
    for (const MatingPose& p : poses) {
      ContactState s;
      a.Evaluate(p, &s);
      interfering += s.interference;
      MatingMotion m;
      m.velocity.y() = 0.01;
      Wrench w;
      gps.Evaluate(s, m, &w);
      ve1.Evaluate(s, m, &w);
      ASSERT_TRUE(w.AllFinite());
    }
    EXPECT_EQ(g_allocations.load() - before, 0) << rows << " rows";
    EXPECT_GT(interfering, 0);
    // The counter works: prepare allocates.
    const long prepare_before = g_allocations.load();
    Eigen::VectorXd map;
    a.InterferenceMap(poses[0], &map);
    EXPECT_GT(g_allocations.load() - prepare_before, 0);
  }
}

// A hand's tick: the god object through the lead-in and in the bore (docs/lead-in.md), the part
// pulled by a finite spring, across clearance and interference, handed over both ways.
TEST(ContactTick, AHandsGodObjectDoesNotAllocate) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  // H7/g6 at 20 mm with the shipped chamfers: C0.5 end, C1 entrance.
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  shaft.size.lower_deviation = -20 * kUm;
  shaft.size.upper_deviation = -7 * kUm;
  bushing.size.upper_deviation = 21 * kUm;
  auto chamfered = [](const PartSpec& part, double length) {
    auto g = std::make_shared<CylindricalGeometry>(
        *static_cast<const CylindricalGeometry*>(part.geometry.get()));
    g->set_chamfer(Chamfer{length, M_PI / 4});
    return g;
  };
  shaft.geometry = chamfered(shaft, 0.5e-3);
  bushing.geometry = chamfered(bushing, 1e-3);
  const int rows = 40, n = 48;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> v(-6 * kUm, 6 * kUm);
  Eigen::VectorXd vs(rows * n), vb(rows / 2 * n);
  for (auto& x : vs) x = v(rng);
  for (auto& x : vb) x = v(rng) + 4 * kUm;
  CylinderContactAnalyzer a;
  a.Prepare(shaft,
            MakeSms(MakeGrid(rows, n, 0.020, 0.040), [&](int i, int j) { return vs[i * n + j]; }),
            bushing,
            MakeSms(MakeGrid(rows / 2, n, 0.020, 0.020), [&](int i, int j) { return vb[i * n + j]; }),
            Settings(0.15, 0.0, TextureMode::kExpected));
  GpsLaw gps;
  gps.Prepare(shaft, bushing, Settings(0.15));
  PositioningStage::Options free_motion;
  free_motion.free_stiffness = 4e4;
  const LeadIn lead_in = MakeCylindricalLeadIn(shaft, bushing);
  const PositioningStage positioning(free_motion, CoarseMeshes{}, Role::kInner, lead_in);
  ConstrainedStage::Options mating;
  mating.depth_origin = positioning.depth_origin();
  mating.proxy_stiffness = free_motion.free_stiffness;
  const ConstrainedStage constrained(a, gps, mating);
  const auto positioning_state = positioning.MakeState();
  const auto constrained_state = constrained.MakeState();
  StageOutput out;
  StageId stage = StageId::kPositioning;
  int constrained_ticks = 0;
  const long before = g_allocations.load();
  // In 1 mm off the axis with a tremor, 24 mm deep, and back out.
  for (int k = 0; k < 4000; ++k) {
    const double t = k * 1e-3;
    PartState d;
    d.position = Eigen::Vector3d(1e-3 + 1e-4 * std::sin(60.0 * t),
                                 -2e-3 + 26e-3 * std::sin(M_PI * t / 4.0),
                                 1e-4 * (std::cos(60.0 * t) - 1.0));
    d.velocity.y() = 26e-3 * M_PI / 4.0 * std::cos(M_PI * t / 4.0);
    if (stage == StageId::kPositioning) {
      positioning.Evaluate(d, positioning_state.get(), &out);
    } else {
      constrained.Evaluate(d, constrained_state.get(), &out);
      ++constrained_ticks;
    }
    ASSERT_TRUE(out.wrench.AllFinite());
    stage = out.next;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_GT(constrained_ticks, 1000);      // it was captured
  EXPECT_EQ(stage, StageId::kPositioning);  // and released
}

}  // namespace
}  // namespace fitfeel::cylindrical
