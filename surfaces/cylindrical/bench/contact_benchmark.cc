// Tick and prepare cost of the cylindrical contact analysis against SMS size, beside a naive
// per-tick scan of every overlapping cell (what the paper's per-tick model costs).
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

// Square-ish grids (m = n) on a 20 mm shaft 40 mm long and a 20 mm bushing with the same row
// pitch (half the rows), H7/g6-like clearance with random form of a few micrometres.
struct Scene {
  PartSpec shaft = MakeShaft(0.020, 0.040);
  PartSpec bushing = MakeBushing(0.020, 0.020, 0.030);
  SkinModelShape s, b;
  int m = 0, n = 0;
  // columns = 0: a square grid (m = n); otherwise n fixed and m = cells / n.
  explicit Scene(long cells, int columns = 0) {
    n = columns > 0 ? columns
                    : static_cast<int>(std::lround(std::sqrt(static_cast<double>(cells))));
    m = static_cast<int>(cells / n);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> v(-2e-6, 2e-6);
    s = MakeSms(MakeGrid(m, n, 0.020, 0.040), [&](int, int) { return -7e-6 + v(rng); });
    b = MakeSms(MakeGrid(m / 2, n, 0.020, 0.020), [&](int, int) { return 3e-6 + v(rng); });
  }
};

void BM_Prepare(benchmark::State& state) {
  Scene sc(state.range(0));
  for (auto _ : state) {
    CylinderContactAnalyzer a;
    a.Prepare(sc.shaft, sc.s, sc.bushing, sc.b, Settings(0.15, 0.0, TextureMode::kSampled));
    benchmark::DoNotOptimize(a.depth_steps());
  }
  state.counters["m"] = sc.m;
  state.counters["n"] = sc.n;
}

void BM_Tick(benchmark::State& state) {
  Scene sc(state.range(0), static_cast<int>(state.range(1)));
  CylinderContactAnalyzer a;
  a.Prepare(sc.shaft, sc.s, sc.bushing, sc.b, Settings(0.15, 0.0, TextureMode::kSampled));
  GpsLaw law;
  law.Prepare(sc.shaft, sc.bushing, Settings(0.15, 2e6));
  MatingPose pose;
  pose.offset = {0.0, -5e-6};
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  double depth = 0.0;
  for (auto _ : state) {
    depth += 1e-5;  // 10 mm/s at 1 kHz
    if (depth > 0.059) depth = 1e-3;
    pose.depth = depth;
    ContactState s;
    a.Evaluate(pose, &s);
    Wrench w;
    law.Evaluate(s, motion, &w);
    benchmark::DoNotOptimize(w);
  }
  state.counters["m"] = sc.m;
  state.counters["n"] = sc.n;
}

// The naive tick: scan every overlapping cell at the pose (rows mapped through axial position)
// for the per-angle minima of S_T minus the axis offset and the interference sum.
void BM_NaiveScanTick(benchmark::State& state) {
  Scene sc(state.range(0), static_cast<int>(state.range(1)));
  const int n = sc.n, ms = sc.m, mb = sc.m / 2;
  std::vector<double> cs(n), sn(n), minima(n);
  for (int j = 0; j < n; ++j) {
    cs[j] = std::cos(sc.s.grid.column_angle[j]);
    sn[j] = std::sin(sc.s.grid.column_angle[j]);
  }
  const double pitch = 0.040 / ms;
  double depth = 0.0;
  for (auto _ : state) {
    depth += 1e-5;
    if (depth > 0.059) depth = 1e-3;
    const double x = 0.0, z = -5e-6;
    double volume = 0.0;
    std::fill(minima.begin(), minima.end(), 1.0);
    for (int i = 0; i < ms; ++i) {
      const double pos = (i + 0.5) * pitch + depth - 0.040;
      if (pos < 0.0 || pos >= 0.020) continue;
      const int k = std::min(mb - 1, static_cast<int>(pos / pitch));
      const double* vs = sc.s.variation.data() + static_cast<long>(i) * n;
      const double* vb = sc.b.variation.data() + static_cast<long>(k) * n;
      for (int j = 0; j < n; ++j) {
        const double gap = vb[j] - vs[j] - (x * cs[j] + z * sn[j]);
        minima[j] = std::min(minima[j], gap);
        volume += gap < 0.0 ? -gap : 0.0;
      }
    }
    benchmark::DoNotOptimize(volume);
    benchmark::DoNotOptimize(minima.data());
  }
}

BENCHMARK(BM_Prepare)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond);
// The paper-case scale (40 x 360 per part, the scenarios' resolution) with an H7/js6-like mix of
// clearance and interference and the expected texture: prepare including the energy minimisation
// at every interfering depth and the texture integral at every depth.
void BM_PreparePaperScale(benchmark::State& state) {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  const TextureSpec t{3.2e-6, 0.4e-6, 1.6e-6};
  shaft.texture = t;
  bushing.texture = t;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> form(-5e-6, 5e-6);
  const int n = 360;
  const SkinModelShape s =
      MakeSms(MakeGrid(40, n, 0.020, 0.040), [&](int, int) { return 0.0 + form(rng); });
  const SkinModelShape b =
      MakeSms(MakeGrid(40, n, 0.020, 0.020), [&](int, int) { return 6.25e-6 + form(rng); });
  int interfering = 0;
  for (auto _ : state) {
    CylinderContactAnalyzer a;
    a.Prepare(shaft, s, bushing, b, Settings(0.15, 0.0, TextureMode::kExpected));
    interfering = 0;
    for (int k = 0; k < a.depth_steps(); ++k) interfering += a.interference_at(k);
    state.counters["newton_iterations"] = a.newton_iterations();
  }
  state.counters["interfering_steps"] = interfering;
}
BENCHMARK(BM_PreparePaperScale)->Unit(benchmark::kMillisecond);

// Square grids, then n fixed at 64 with m growing: the tick depends on n only. (A fixed-n grid of
// 10^6 cells has m = 15625 rows; its O(m^2 n) prepare takes minutes, so it is left out.)
static void TickArgs(benchmark::internal::Benchmark* b) {
  for (long cells : {1000L, 10000L, 100000L, 1000000L}) b->Args({cells, 0});
  for (long cells : {1024L, 10240L, 102400L}) b->Args({cells, 64});
}
BENCHMARK(BM_Tick)->Apply(TickArgs)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_NaiveScanTick)->Apply(TickArgs)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace fitfeel::cylindrical
