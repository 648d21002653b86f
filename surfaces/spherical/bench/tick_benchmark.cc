// Cost of one tick (analyzer Evaluate + law Evaluate) of the knuckle bearing: one pass over the
// socket's cells with a bilinear lookup of the turned ball, linear in m x n.
#include <benchmark/benchmark.h>

#include "framework/testing/tick_benchmark.h"
#include "surfaces/spherical/spherical_contact_analyzer.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/spherical_law.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

void BM_SphericalTick(benchmark::State& state) {
  PartSpec ball = test::Ball();
  PartSpec socket = test::Socket();
  ball.size.lower_deviation = -21e-6;
  socket.size.upper_deviation = 21e-6;
  ball.form.tolerance[FormCharacteristic::kRoundness] = 6e-6;
  socket.form.tolerance[FormCharacteristic::kSphericity] = 9e-6;
  const Resolution r = test_support::BenchmarkGrid(state);
  ModelSettings settings;
  settings.friction = 0.15;
  settings.contact_stiffness = 1e6;
  SphericalContactAnalyzer analyzer;
  KnuckleBearingLaw law;
  test_support::PreparePair<SphericalDiscretizer, SphericalVariationGenerator>(
      ball, socket, r, settings, &analyzer, &law);
  MatingMotion motion;
  motion.angular_velocity.y() = 1.0;
  test_support::TimeTicks(state, analyzer, law, motion, [angle = 0.0]() mutable {
    MatingPose pose;
    pose.angle = angle;
    pose.offset = Eigen::Vector2d(0.0, -30e-6);
    angle += 1e-3;
    return pose;
  });
  state.counters["cells"] = static_cast<double>(r.rows) * r.columns;
}
BENCHMARK(BM_SphericalTick)->Args({12, 72})->Args({40, 360});

}  // namespace
}  // namespace fitfeel::spherical
