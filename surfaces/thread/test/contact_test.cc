// The thread's contact and flank law on prepared skin model shapes: the screw's free play, the
// lead's share of the torque, and friction along the helix.
#include <cmath>
#include <memory>
#include <numbers>

#include <gtest/gtest.h>

#include "framework/plugin/registry.h"
#include "framework/runtime/prepare.h"
#include "framework/scenario/scene.h"
#include "surfaces/thread/thread_contact_analyzer.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_law.h"
#include "surfaces/thread/thread_options.h"
#include "surfaces/thread/turn_load_distribution.h"

namespace fitfeel::thread {
namespace {

constexpr const char* kScenario = "surfaces/thread/test/conformance.yaml";

struct Prepared {
  Scene scene;
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
  double play_phase = 0.0;  // the screw phase at which flank A meets, m
};

// The conformance scene without form deviations at `seed`, and where its flank A first meets:
// the normal gap of the drawn pitch diameters over the largest n_y.
Prepared PrepareThread(std::uint64_t seed, double friction, bool form = false) {
  static PluginRegistry* registry = [] {
    auto* r = new PluginRegistry();
    r->LoadAll();
    return r;
  }();
  Prepared p;
  p.scene = LoadScene(kScenario, *registry);
  if (!form) {
    p.scene.inner.form.declared.clear();
    p.scene.outer.form.declared.clear();
  }
  p.scene.model.friction = p.scene.model.static_friction = friction;
  Rng rng(seed);
  const SkinModelShapes shapes = GenerateSkinModelShapes(p.scene, rng);
  p.analyzer = p.scene.surface->MakeContactAnalyzer();
  p.analyzer->Prepare(p.scene.inner, shapes.inner, p.scene.outer, shapes.outer, p.scene.model);
  p.law = p.scene.surface->MakeLaw("flank");
  p.law->Prepare(p.scene.inner, p.scene.outer, p.scene.model);
  const HelicoidGeometry& g = HelicoidGeometryOf(p.scene.inner);
  const double k = std::tan(g.half_angle()), c = g.pitch() / (2 * std::numbers::pi);
  const double r = g.outer_radius();
  const double gap = shapes.outer.variation[0] - shapes.inner.variation[0];
  p.play_phase = gap * std::sqrt(1 + k * k + c * c / (r * r));
  return p;
}

Wrench At(const Prepared& p, double depth, double angle, double spin) {
  MatingPose pose;
  pose.depth = depth;
  pose.angle = angle;
  ContactState contact;
  p.analyzer->Evaluate(pose, &contact);
  MatingMotion motion;
  motion.angular_velocity.y() = spin;
  motion.velocity.y() = 0.01;
  Wrench w;
  p.law->Evaluate(contact, motion, &w);
  return w;
}

TEST(ThreadContact, RunsFreeWithinThePlayOfItsPitchDiameters) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Prepared p = PrepareThread(seed, 0.12);
    ASSERT_GT(p.play_phase, 0.0);
    const double lead = 1.5e-3 / (2 * std::numbers::pi);
    for (const double angle : {0.0, 1.0, 10.0, 30.0}) {
      const double depth = 7.5e-3 + lead * angle;
      for (const double u : {0.0, 0.95 * p.play_phase, -0.95 * p.play_phase}) {
        const Wrench w = At(p, depth + u, angle, 1.0);
        EXPECT_EQ(w.force.norm() + w.torque.norm(), 0.0) << "seed " << seed << " u " << u;
      }
      // Past the play the leading flank pushes the part back along the axis.
      EXPECT_LT(At(p, depth + 1.2 * p.play_phase, angle, 1.0).force.y(), 0.0);
      EXPECT_GT(At(p, depth - 1.2 * p.play_phase, angle, 1.0).force.y(), 0.0);
    }
  }
}

TEST(ThreadContact, AFrictionlessScrewTurnsWithTheLeadOnly) {
  // A force normal to the flanks does no work along the screw (d(angle), P d(angle) / 2 pi) that
  // keeps them in contact: T + F P / 2 pi = 0, whatever the flank band or the pressure's spread.
  const Prepared p = PrepareThread(3, 0.0);
  for (const double push : {1.5, 3.0, 10.0}) {
    const Wrench w = At(p, 7.5e-3 + push * p.play_phase, 0.0, 1.0);
    ASSERT_LT(w.force.y(), 0.0);
    EXPECT_NEAR(w.torque.y() / w.force.y(), -1.5e-3 / (2 * std::numbers::pi), 1e-12);
  }
}

// The assembly space: the offsets of the bolt's axis that touch nothing at a pose. Inside it (its
// vertices pulled halfway to their centre) no cell interferes; the conformance suite checks that
// beyond it every vertex touches.
TEST(ThreadContact, InsideItsAssemblySpaceTheBoltTouchesNothing) {
  // Without pitch and flank-angle deviations (which, accumulated over the turns, can leave no
  // offset free at the screw's nominal phase) the pitch diameters' play is free all round.
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Prepared p = PrepareThread(seed, 0.12);
    const double lead = 1.5e-3 / (2 * std::numbers::pi);
    for (const double angle : {0.0, 2.0, 17.0}) {
      MatingPose pose;
      pose.depth = 7.5e-3 + lead * angle;
      pose.angle = angle;
      std::vector<Eigen::Vector2d> polygon;
      ASSERT_TRUE(p.analyzer->AssemblySpace(pose, &polygon));
      ASSERT_FALSE(polygon.empty()) << "seed " << seed;
      Eigen::Vector2d centre = Eigen::Vector2d::Zero();
      for (const auto& v : polygon) centre += v / static_cast<double>(polygon.size());
      for (const auto& v : polygon) {
        pose.offset = centre + 0.5 * (v - centre);
        ContactState contact;
        p.analyzer->Evaluate(pose, &contact);
        EXPECT_EQ(contact.interference_volume, 0.0) << "seed " << seed;
      }
    }
  }
}

// Sopwith's distribution: the flank stiffness weighted along the nut so that a uniform
// interference carries his shares of the load, the turn at the bearing face most.
TEST(ThreadContact, SopwithsDistributionLoadsTheFirstTurnMost) {
  Prepared p = PrepareThread(2, 0.12);
  auto options = std::make_shared<ThreadOptions>();
  options->distribution = LoadDistribution::kSopwith;
  p.scene.model.options = options;
  p.scene.model.contact_stiffness = 0.0;  // auto: VDI 2230's engaged thread
  Rng rng(2);
  const SkinModelShapes shapes = GenerateSkinModelShapes(p.scene, rng);
  ThreadContactAnalyzer analyzer;
  analyzer.Prepare(p.scene.inner, shapes.inner, p.scene.outer, shapes.outer, p.scene.model);
  const double length = 15e-3, pitch = 1.5e-3;
  EXPECT_GT(analyzer.LoadWeight(0.0), 1.5 * analyzer.LoadWeight(0.5 * length));
  EXPECT_GT(analyzer.LoadWeight(0.5 * length), analyzer.LoadWeight(length));
  // Turn by turn the weights are in Sopwith's proportions (the shares of the library's closed
  // form, whatever the common scale).
  auto turn = [&](int i) {
    double sum = 0.0;
    for (int k = 0; k < 100; ++k) sum += analyzer.LoadWeight((i + (k + 0.5) / 100) * pitch);
    return sum;
  };
  const double lambda = std::acosh(analyzer.LoadWeight(0.0) / analyzer.LoadWeight(length));
  const std::vector<double> shares = TurnLoadShares(length, pitch, lambda / length);
  EXPECT_NEAR(turn(0) / turn(4), shares[0] / shares[4], 1e-3 * shares[0] / shares[4]);
}

}  // namespace
}  // namespace fitfeel::thread
