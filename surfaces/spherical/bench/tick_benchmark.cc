// Cost of one tick (analyzer Evaluate + law Evaluate) of the knuckle bearing: one pass over the
// socket's cells with a bilinear lookup of the turned ball, linear in m x n.
#include <benchmark/benchmark.h>

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
  const Resolution r{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
  ModelSettings settings;
  settings.friction = 0.15;
  settings.contact_stiffness = 1e6;
  Rng rng(1);
  const SkinModelShape ball_sms = SphericalVariationGenerator().Generate(
      ball, SphericalDiscretizer().Discretize(ball, r), TextureMode::kExpected, rng);
  const SkinModelShape socket_sms = SphericalVariationGenerator().Generate(
      socket, SphericalDiscretizer().Discretize(socket, r), TextureMode::kExpected, rng);
  SphericalContactAnalyzer analyzer;
  analyzer.Prepare(ball, ball_sms, socket, socket_sms, settings);
  KnuckleBearingLaw law;
  law.Prepare(ball, socket, settings);
  MatingMotion motion;
  motion.angular_velocity.y() = 1.0;
  ContactState contact;
  Wrench wrench;
  double angle = 0.0;
  for (auto _ : state) {
    MatingPose pose;
    pose.angle = angle;
    pose.offset = Eigen::Vector2d(0.0, -30e-6);
    analyzer.Evaluate(pose, &contact);
    law.Evaluate(contact, motion, &wrench);
    benchmark::DoNotOptimize(wrench);
    angle += 1e-3;
  }
  state.counters["cells"] = static_cast<double>(r.rows) * r.columns;
}
BENCHMARK(BM_SphericalTick)->Args({12, 72})->Args({40, 360});

}  // namespace
}  // namespace fitfeel::spherical
