// The tick path must not allocate: this binary counts every heap allocation and runs the analyzer's
// and the laws' Evaluate over many poses.
#include <atomic>
#include <cstdlib>
#include <random>

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
constexpr double kUm = 1e-6;

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

}  // namespace
}  // namespace fitfeel::cylindrical
