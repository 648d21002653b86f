#include "framework/model/friction.h"

#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

// Lubricated hard steel (handbook middles) and the steel junctions' breakaway displacement.
const FrictionParameters kSteel{0.17, 0.075, 2e-6};

Eigen::Vector2d Axial(double y) { return {y, 0.0}; }

TEST(StickSlipFriction, RefusesCoefficientsThatCannotBe) {
  EXPECT_THROW(StickSlipFriction({0.1, 0.2, 2e-6}), UserError);   // kinetic above static
  EXPECT_THROW(StickSlipFriction({0.2, -0.1, 2e-6}), UserError);  // negative
  EXPECT_THROW(StickSlipFriction({0.2, 0.1, 0.0}), UserError);    // no presliding length
  EXPECT_THROW(StickSlipFriction({NAN, 0.1, 2e-6}), UserError);
  EXPECT_NO_THROW(StickSlipFriction({0.2, 0.2, 2e-6}));            // Coulomb with stiction
}

// A part pushed below mu_s N stays put: the junctions deflect by push / k and hold, whatever the
// push's history below the threshold.
TEST(StickSlipFriction, HoldsAnyPushBelowTheStaticLevel) {
  const StickSlipFriction friction(kSteel);
  const double normal = 1000.0;  // N
  const double k = friction.StickingStiffness(normal);
  EXPECT_DOUBLE_EQ(k, 0.17 * 1000.0 / 2e-6);
  FrictionState state;
  EXPECT_EQ(friction.Step(Axial(0.0), normal, &state), Eigen::Vector2d::Zero());
  for (double push : {10.0, 80.0, 169.0, -169.0, 120.0}) {  // all below mu_s N = 170 N
    // A quasi-static part where the push balances the junctions' spring: y = push / k.
    const Eigen::Vector2d f = friction.Step(Axial(push / k), normal, &state);
    EXPECT_NEAR(f.x(), -push, 1e-9 * normal);
    EXPECT_FALSE(state.sliding);
    EXPECT_EQ(state.anchor, Eigen::Vector2d::Zero());  // the contact never moved
  }
}

// Above mu_s N the junctions break and the part slides against mu_k N; when it stops, it sticks
// again and must be pushed to mu_s N anew.
TEST(StickSlipFriction, BreaksAwayAtStaticSlidesAtKineticSticksAgain) {
  const StickSlipFriction friction(kSteel);
  const double normal = 500.0;
  FrictionState state;
  friction.Step(Axial(0.0), normal, &state);
  double peak = 0.0;
  double y = 0.0;
  for (int i = 0; i < 200; ++i) {  // 10 mm/s at 1 kHz: 10 um per tick
    y += 0.1e-6;                   // finer steps resolve the breakaway
    const Eigen::Vector2d f = friction.Step(Axial(y), normal, &state);
    peak = std::max(peak, -f.x());
  }
  EXPECT_NEAR(peak, 0.17 * normal, 0.17 * normal * 0.05 + 1e-9);  // within one step of z_s
  EXPECT_LE(peak, 0.17 * normal * (1.0 + 1e-12));                  // never above mu_s N
  EXPECT_TRUE(state.sliding);
  for (int i = 0; i < 50; ++i) {
    y += 10e-6;
    EXPECT_NEAR(friction.Step(Axial(y), normal, &state).x(), -0.075 * normal, 1e-9);
  }
  // Stop: the force stays at mu_k N (the junctions' deflection holds) and the contact sticks.
  EXPECT_NEAR(friction.Step(Axial(y), normal, &state).x(), -0.075 * normal, 1e-9);
  EXPECT_FALSE(state.sliding);
  // Pull back a little: the spring unloads through zero and reverses, still sticking.
  const double k = friction.StickingStiffness(normal);
  const double rest = y - 0.075 * normal / k;
  EXPECT_NEAR(friction.Step(Axial(rest), normal, &state).x(), 0.0, 1e-9);
  EXPECT_NEAR(friction.Step(Axial(rest - 50.0 / k), normal, &state).x(), 50.0, 1e-6);  // < 85 N
  EXPECT_FALSE(state.sliding);
}

// Released normal force lets the junctions go; the next contact forms where it happens.
TEST(StickSlipFriction, ReleasedContactForgetsItsAnchor) {
  const StickSlipFriction friction(kSteel);
  FrictionState state;
  friction.Step(Axial(0.0), 100.0, &state);
  friction.Step(Axial(1e-6), 100.0, &state);
  EXPECT_EQ(friction.Step(Axial(1e-3), 0.0, &state), Eigen::Vector2d::Zero());
  EXPECT_FALSE(state.anchored);
  EXPECT_EQ(friction.Step(Axial(2e-3), 100.0, &state), Eigen::Vector2d::Zero());
  EXPECT_EQ(state.anchor, Axial(2e-3));
}

// The force only depends on positions: the spring stores at most mu_s N z_s / 2 and the work the
// contact does on the part over any closed path is never positive (passivity of the element).
TEST(StickSlipFriction, ClosedPathsDissipate) {
  const StickSlipFriction friction(kSteel);
  const double normal = 200.0;
  FrictionState state;
  Eigen::Vector2d x(0.0, 0.0);
  friction.Step(x, normal, &state);
  double work = 0.0;  // on the part, trapezoidal in the position
  Eigen::Vector2d f_prev = Eigen::Vector2d::Zero();
  for (int i = 1; i <= 4000; ++i) {
    // A wandering two-dimensional path (axial and circumferential) of a few um that returns.
    const double t = 2.0 * M_PI * i / 4000.0;
    const Eigen::Vector2d next(5e-6 * std::sin(3.0 * t), 3e-6 * std::sin(7.0 * t));
    const Eigen::Vector2d f = friction.Step(next, normal, &state);
    work += 0.5 * (f + f_prev).dot(next - x);
    f_prev = f;
    x = next;
    EXPECT_LE(f.norm(), 0.17 * normal * (1.0 + 1e-12));
  }
  const double stored_max = 0.5 * 0.17 * normal * 2e-6;
  EXPECT_LT(work, stored_max);  // what the spring may give back, nothing more
  EXPECT_LT(work, 0.0);         // a path that slips dissipates
}

TEST(StickSlipFriction, SmoothedIsKineticCoulombAwayFromRest) {
  const StickSlipFriction friction(kSteel);
  EXPECT_NEAR(friction.Smoothed({10e-3, 0.0}, 100.0).x(), -7.5, 1e-6);
  EXPECT_EQ(friction.Smoothed({0.0, 0.0}, 100.0), Eigen::Vector2d::Zero());
  EXPECT_EQ(friction.Smoothed({1.0, 0.0}, 0.0), Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace fitfeel
