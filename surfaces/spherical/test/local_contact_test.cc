// The loaded bearing's local contact with its rings' walls (local_contact.h) against its two
// closed-form limits: half-spaces (conformal Hertz) and thin walls (a Winkler bed).
#include "surfaces/spherical/local_contact.h"

#include <cmath>

#include <limits>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "framework/core/error.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

constexpr double kNu = 0.3;

// Long waves compress the layer without lateral strain, short ones see a half-space.
TEST(BondedLayer, FactorRunsFromTheConfinedLayerToTheHalfSpace) {
  const double confined = (1.0 - 2.0 * kNu) / (2.0 * (1.0 - kNu) * (1.0 - kNu));
  EXPECT_NEAR(BondedLayerFactor(1e-4, kNu) / 1e-4, confined, 1e-6);
  EXPECT_NEAR(BondedLayerFactor(8.0, kNu), 1.0, 1e-4);
  EXPECT_EQ(BondedLayerFactor(30.0, kNu), 1.0);
  double previous = 0.0;
  for (double x = 1e-3; x < 20.0; x *= 1.1) {
    const double k = BondedLayerFactor(x, kNu);
    EXPECT_GT(k, previous) << x;
    EXPECT_LE(k, 1.0) << x;
    previous = k;
  }
}

// Navier's equations for the mode u_x = U(z) sin kx, u_z = W(z) cos kx (k = 1), integrated from
// the bonded base (U = W = 0) by classical Runge-Kutta for the two free slopes, combined so that
// the face at z = h carries sigma_zz = -1, sigma_xz = 0: W(h) against the half-space's
// 2 (1 - nu^2) / (E k).
double NaviersLayerFactor(double h) {
  const double e = 1.0, lambda = e * kNu / ((1.0 + kNu) * (1.0 - 2.0 * kNu));
  const double mu = e / (2.0 * (1.0 + kNu));
  using State = Eigen::Vector4d;  // U, U', W, W'
  const auto slope = [&](const State& y) {
    return State(y[1], ((lambda + 2.0 * mu) * y[0] + (lambda + mu) * y[3]) / mu, y[3],
                 (mu * y[2] - (lambda + mu) * y[1]) / (lambda + 2.0 * mu));
  };
  const auto face = [&](State y) {
    constexpr int kSteps = 4000;
    const double dz = h / kSteps;
    for (int i = 0; i < kSteps; ++i) {
      const State a = slope(y), b = slope(y + 0.5 * dz * a), c = slope(y + 0.5 * dz * b),
                  d = slope(y + dz * c);
      y += dz / 6.0 * (a + 2.0 * b + 2.0 * c + d);
    }
    return y;
  };
  const State from_u = face(State(0.0, 1.0, 0.0, 0.0)), from_w = face(State(0.0, 0.0, 0.0, 1.0));
  const auto traction = [&](const State& y) {
    return Eigen::Vector2d(lambda * (y[0] + y[3]) + 2.0 * mu * y[3], mu * (y[1] - y[2]));
  };
  Eigen::Matrix2d system;
  system << traction(from_u), traction(from_w);
  const Eigen::Vector2d mix = system.partialPivLu().solve(Eigen::Vector2d(-1.0, 0.0));
  const double w = mix[0] * from_u[2] + mix[1] * from_w[2];
  return std::abs(w) / (2.0 * (1.0 - kNu * kNu) / e);
}

TEST(BondedLayer, FactorIsNaviersSolution) {
  for (const double x : {0.05, 0.2, 0.5, 1.0, 2.0, 4.0}) {
    EXPECT_NEAR(BondedLayerFactor(x, kNu), NaviersLayerFactor(x), 1e-9) << x;
  }
}

// Walls far thicker than the patch: Hertz's load, radius and peak pressure.
TEST(LocalContact, ThickWallsGiveConformalHertz) {
  const Material steel = test::Steel();
  const LayeredConformalContact walls(14.5e-3, {steel, 10.0}, {steel, 10.0});
  const double e_star = ContactModulus(steel, steel);
  for (const double approach : {0.2e-6, 1e-6, 3e-6}) {
    const HertzContact hertz = LocalContact(14.5e-3, 30e-6, approach, e_star);
    const HertzContact h = walls.Load(30e-6, approach);
    EXPECT_NEAR(h.load / hertz.load, 1.0, 2e-3) << approach;
    EXPECT_NEAR(h.radius / hertz.radius, 1.0, 5e-3) << approach;
    EXPECT_NEAR(h.peak_pressure / hertz.peak_pressure, 1.0, 5e-3) << approach;
  }
  // Two solid parts: exactly Hertz.
  const LayeredConformalContact solid(14.5e-3, {steel}, {steel});
  EXPECT_EQ(solid.Load(30e-6, 1e-6).load, LocalContact(14.5e-3, 30e-6, 1e-6, e_star).load);
}

// The gap's curvature is the offset's: spheres R1 = 14.5 mm and R2 = R1 + c with their centres
// e = c + delta apart, the exact gap along the socket's normal at the angle phi,
// R2 - |R2 (cos phi, sin phi) - (e, 0)| - R1 (sign: positive open), against r^2 / (2R) - delta
// with r = R1 phi at small phi: R = R1 R2 / e, not Hertz's R1 R2 / c.
TEST(LocalContact, GapCurvatureIsTheCentresDistances) {
  const double r1 = 14.5e-3, c = 30e-6, delta = 2e-6, e = c + delta, r2 = r1 + c;
  const double phi = 0.02;
  const double to_ball = std::hypot(r2 * std::cos(phi) - e, r2 * std::sin(phi));
  const double gap = to_ball - r1;  // the ball's surface along the same ray
  const double curvature = 2.0 * (gap + delta) / std::pow(r1 * phi, 2);  // 1 / R
  EXPECT_NEAR(1.0 / curvature, r1 * r2 / e, 0.005 * r1 * r2 / e);        // to first order in e / R
  EXPECT_GT(std::abs(1.0 / curvature - r1 * r2 / c), 0.05 * r1 * r2 / c);
  // LocalContact's patch radius is sqrt(R delta) with that R.
  const HertzContact h = LocalContact(r1, c, delta, ContactModulus(test::Steel(), test::Steel()));
  EXPECT_NEAR(h.radius, std::sqrt(r1 * r2 / e * delta), 1e-12);
}

// Walls far thinner than the patch: each a bed of stiffness M / h (M = E (1 - nu) / ((1 + nu)
// (1 - 2 nu)), the confined modulus), so p = k (delta - r^2 / (2R)) out to sqrt(2 R delta) and
// W = pi k R delta^2. R1 = 1 m, c = 1 mm, delta = 1 um (R = R1 R2 / (c + delta) = 1000 m): a = 45
// mm over walls of 0.3 and 0.5 mm; the edges' transition costs O(h / a).
TEST(LocalContact, ThinWallsGiveAWinklerBed) {
  const Material steel = test::Steel();
  const double m = steel.youngs_modulus * (1.0 - kNu) / ((1.0 + kNu) * (1.0 - 2.0 * kNu));
  const double k = m / (0.3e-3 + 0.5e-3);
  const LayeredConformalContact walls(1.0, {steel, 0.3e-3}, {steel, 0.5e-3});
  const double r = 1.0 * 1.001 / 1.001e-3, delta = 1e-6;
  const HertzContact h = walls.Load(1e-3, delta);
  const double winkler = std::numbers::pi * k * r * delta * delta;
  EXPECT_NEAR(h.load / winkler, 1.0, 0.03);
  EXPECT_NEAR(h.radius / std::sqrt(2.0 * r * delta), 1.0, 0.03);
  EXPECT_NEAR(h.peak_pressure / (k * delta), 1.0, 0.03);
  EXPECT_GT(h.load, 5.0 * LocalContact(1.0, 1e-3, delta, ContactModulus(steel, steel)).load);
  // Past s = kBed the ratios carry on from the table's last point without a step.
  const double bed = LayeredConformalContact::kBed;
  const auto below = walls.RatiosAt(bed * (1.0 - 1e-9));
  const auto above = walls.RatiosAt(bed * (1.0 + 1e-9));
  EXPECT_NEAR(below.load / above.load, 1.0, 1e-8);
  EXPECT_NEAR(below.radius / above.radius, 1.0, 1e-8);
  EXPECT_NEAR(below.peak_pressure / above.peak_pressure, 1.0, 1e-8);
}

// The settling search needs the support monotone in the approach, at every clearance, and the
// table continuous where it hands over to its a / h fade below its first point.
TEST(LocalContact, LoadGrowsWithTheApproachAtEveryClearance) {
  const Material steel = test::Steel();
  const LayeredConformalContact walls(14.5e-3, {steel, 4.5e-3}, {steel, 2.97e-3});
  for (const double clearance : {5e-6, 20e-6, 40e-6, 82e-6}) {
    double previous = 0.0;
    for (double approach = 1e-9; approach < 2.0 * clearance; approach *= 1.05) {
      const double load = walls.Load(clearance, approach).load;
      ASSERT_GE(load, previous * (1.0 - 1e-12)) << clearance << " " << approach;
      previous = load;
    }
  }
  const double lowest =
      std::pow(kHertzMaxSpread * 14.5e-3 / 2.97e-3, 2) / LayeredConformalContact::kSpan;
  const auto below = walls.RatiosAt(lowest * (1.0 - 1e-9));
  const auto above = walls.RatiosAt(lowest * (1.0 + 1e-9));
  EXPECT_NEAR(below.load, above.load, 1e-8);
  EXPECT_NEAR(below.peak_pressure, above.peak_pressure, 1e-8);
  EXPECT_EQ(walls.RatiosAt(0.0).load, 1.0);
}

TEST(LocalContact, RefusesWhatIsNotAContact) {
  const Material steel = test::Steel();
  EXPECT_THROW(LayeredConformalContact(0.0, {steel, 1e-3}, {steel, 1e-3}), UserError);
  EXPECT_THROW(LayeredConformalContact(1e-2, {steel, 0.0}, {steel, 1e-3}), UserError);
  EXPECT_THROW(LayeredConformalContact(1e-2, {steel, 1e-3}, {Material{"x", 0.0, 0.3}, 1e-3}),
               UserError);
  const LayeredConformalContact walls(1e-2, {steel, 1e-3}, {steel, 1e-3});
  EXPECT_EQ(walls.Load(0.0, 1e-6).load, 0.0);
  EXPECT_EQ(walls.Load(30e-6, 0.0).load, 0.0);
  EXPECT_EQ(walls.Load(std::numeric_limits<double>::quiet_NaN(), 1e-6).load, 0.0);
}

}  // namespace
}  // namespace fitfeel::spherical
