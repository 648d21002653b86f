// The thick spherical shell oracle (docs/oracles.md: a = 10 mm, b = 15 mm, steel,
// delta = 1 um -> p = 14.07 MPa) through the analyzer and law with zero form and texture and a
// uniform interference, and the friction torque against its integral.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/core/wrench.h"
#include "framework/testing/fem_data.h"
#include "surfaces/spherical/spherical_contact_analyzer.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/spherical_law.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

constexpr double kMu = 0.1;
constexpr double kA = 10e-3;
constexpr double kB = 10e-3;  // socket band width

// The band's ring coefficient written out independently of the law (midpoint rule over slices
// of the band, each slice Lame's disc in a ring at radius r = sqrt(a^2 - y^2), steel):
// a * integral P(r) dy / integral r dy, with a ball bore d (0: solid).
double BandCoefficient(double a, double band, double ring_diameter, double bore = 0.0) {
  const double E = 210e9, nu = 0.3, b = 0.5 * ring_diameter, c = 0.5 * bore;
  const int steps = 100000;
  double pressure = 0.0, radius = 0.0;
  for (int s = 0; s < steps; ++s) {
    const double y = -band / 2 + (s + 0.5) * band / steps;
    const double r = std::sqrt(a * a - y * y);
    const double ball = (r * r + c * c) / (r * r - c * c) - nu;
    const double ring = (b * b + r * r) / (b * b - r * r) + nu;
    pressure += (1.0 / r) / ((ball + ring) / E);
    radius += r;
  }
  return a * pressure / radius;
}

struct Model {
  SphericalContactAnalyzer analyzer;
  KnuckleBearingLaw law;
};

// A ball of actual diameter nominal + 2 * interference (every two-point size the same) in a
// perfect socket: a uniform radial interference. A ball with form needs a size zone (`zone`,
// diametral, centred on that size) for its two-point sizes to vary in; with none the generator's
// final clamp removes all form.
void Prepare(Model* model, PartSpec ball, PartSpec socket, Resolution resolution,
             double interference, std::uint64_t seed = 1, double zone = 0.0) {
  ball.size.lower_deviation = 2.0 * interference - 0.5 * zone;
  ball.size.upper_deviation = 2.0 * interference + 0.5 * zone;
  ModelSettings settings;
  settings.friction = kMu;
  settings.contact_stiffness = 1e6;
  Rng rng(seed);
  const SphericalDiscretizer discretizer;
  const SphericalVariationGenerator generator;
  const SkinModelShape ball_sms = generator.Generate(ball, discretizer.Discretize(ball, resolution),
                                                     TextureMode::kExpected, rng);
  const SkinModelShape socket_sms = generator.Generate(
      socket, discretizer.Discretize(socket, resolution), TextureMode::kExpected, rng);
  model->analyzer.Prepare(ball, ball_sms, socket, socket_sms, settings);
  model->law.Prepare(ball, socket, settings);
}

Wrench Evaluate(const Model& model, double angle, double spin,
                Eigen::Vector2d offset = Eigen::Vector2d::Zero(), ContactState* state = nullptr) {
  MatingPose pose;
  pose.angle = angle;
  pose.offset = offset;
  ContactState contact;
  model.analyzer.Evaluate(pose, &contact);
  if (state != nullptr) *state = contact;
  MatingMotion motion;
  motion.angular_velocity.y() = spin;
  Wrench wrench;
  model.law.Evaluate(contact, motion, &wrench);
  return wrench;
}

TEST(ThickShell, MatchesTheOracle) {
  const double p = ThickShellPressurePerInterference(10e-3, 15e-3, test::Steel(), test::Steel());
  EXPECT_NEAR(p * 1e-6 * 1e-6, 14.07, 0.005);  // MPa at 1 um
  RecordProperty("pressure_MPa_at_1um", std::to_string(p * 1e-12));
}

TEST(KnuckleBearing, UniformInterferenceGivesTheShellPressureOverTheBand) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{20, 72}, 1e-6);
  ContactState contact;
  const Wrench w = Evaluate(model, 0.0, 0.0, Eigen::Vector2d::Zero(), &contact);
  const double band = 2.0 * M_PI * kA * kB;
  EXPECT_TRUE(contact.engaged);
  EXPECT_NEAR(contact.engaged_area, band, 1e-12 * band);
  EXPECT_NEAR(contact.interference_volume, 1e-6 * band, 1e-12 * band * 1e-6);
  EXPECT_NEAR(contact.max_interference, 1e-6, 1e-18);
  // Sum p ds = p * 2 pi a B; symmetric: no radial force, and no torque at rest.
  // The ring of outer diameter 30 mm around a solid ball's 10 mm band, slice by slice: at the
  // equator Lame's cylinder, the oracle's 5.8333 MPa per um (d1 = 20 mm, d2 = 30 mm, steel);
  // towards the band's edges the ring's wall thickens, 6.3 MPa per um over the band.
  EXPECT_NEAR(RingPressurePerInterference(2.0 * kA, 30e-3, test::Steel(), test::Steel()) * 1e-12,
              5.8333, 0.0005);
  const double p = model.law.pressure_per_interference() * 1e-6;
  EXPECT_NEAR(p, BandCoefficient(kA, kB, 30e-3) * 1e-6, 1e-8 * p);
  EXPECT_NEAR(w.force.norm(), 0.0, 1e-9 * p * band);
  EXPECT_EQ(w.torque.y(), 0.0);
}

TEST(KnuckleBearing, ReportsTheRingCoefficientOfItsForcesForPressureMaps) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{20, 72}, 1e-6);
  // The band's slices of Lame cylinders (BandCoefficient); the thick shell of radii 10 and 15 mm
  // would give 14.07 MPa per um.
  const double expected = BandCoefficient(kA, kB, 30e-3);
  EXPECT_NEAR(model.law.PressurePerInterference(), expected, 1e-8 * expected);
  // The coefficient is the one behind the forces: the ball offset by e in the uniform 1 um
  // interference is pushed back by P * sum(delta ds n), the analyzer's resultant.
  ContactState contact;
  const Wrench w = Evaluate(model, 0.0, 0.0, Eigen::Vector2d(0.0, -0.5e-6), &contact);
  ASSERT_GT(contact.pressure_resultant.norm(), 0.0);
  EXPECT_NEAR(w.force.z(), -model.law.PressurePerInterference() * contact.pressure_resultant.y(),
              1e-9 * std::abs(w.force.z()));
}

TEST(KnuckleBearing, FrictionTorqueIsMuTimesThePressureMoment) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{20, 72}, 1e-6);
  const double p = BandCoefficient(kA, kB, 30e-3) * 1e-6;
  // mu * integral over the band of p * (distance from the axis) dA, dA = 2 pi a dy, numerically.
  double moment = 0.0;
  const int steps = 200000;
  for (int s = 0; s < steps; ++s) {
    const double y = -kB / 2 + (s + 0.5) * kB / steps;
    moment += p * std::sqrt(kA * kA - y * y) * 2.0 * M_PI * kA * kB / steps;
  }
  const double expected = kMu * moment;
  // 10 rad/s: slip 0.1 m/s = 100 smoothing velocities, Coulomb to double precision.
  const Wrench w = Evaluate(model, 0.3, 10.0);
  EXPECT_NEAR(w.torque.y(), -expected, 1e-9 * expected);
  EXPECT_NEAR(Evaluate(model, 0.3, -10.0).torque.y(), expected, 1e-9 * expected);
  // The brief's simplified mu * sum p ds * a overstates it by the arm ratio a / rho_mean.
  const double simplified = kMu * p * 2.0 * M_PI * kA * kB * kA;
  EXPECT_GT(simplified, expected);
  EXPECT_NEAR(simplified / expected, kA / GeometryOf(test::Socket()).mean_axis_distance(), 1e-9);
  RecordProperty("torque_Nm", std::to_string(expected));
  RecordProperty("torque_simplified_Nm", std::to_string(simplified));
  // Smooth through zero speed: tanh(1) of Coulomb at the smoothing velocity.
  const double rho = model.law.friction_arm();
  EXPECT_NEAR(Evaluate(model, 0.3, kFrictionSmoothingVelocity / rho).torque.y(),
              -expected * std::tanh(1.0), 1e-9 * expected);
}

TEST(KnuckleBearing, RadialOffsetGivesTheBandsRadialStiffness) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{40, 72}, 1e-6);
  // Offset e smaller than the interference keeps every cell in contact: delta = 1 um + e n_x, so
  // F_x = -P e sum(n_x^2 ds) = -P e pi a (B - B^3 / (12 a^2)).
  const double e = 0.4e-6;
  const double P = model.law.pressure_per_interference();
  const double expected = -P * e * M_PI * kA * (kB - kB * kB * kB / (12.0 * kA * kA));
  const Wrench w = Evaluate(model, 0.0, 0.0, Eigen::Vector2d(e, 0.0));
  // The cells sample n_x^2 = (1 - y^2/a^2) cos^2 at row centres (midpoint rule): relative error
  // (h / a)^2 / 12 = 5.2e-5 for h = 0.25 mm; nothing else may differ.
  const double h = kB / 40;
  EXPECT_NEAR(w.force.x(), expected, 1.2 * (h / kA) * (h / kA) / 12.0 * std::abs(expected));
  EXPECT_NEAR(w.force.z(), 0.0, 1e-9 * std::abs(expected));
}

TEST(KnuckleBearing, ClearanceUntilTheOffsetClosesIt) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{12, 72}, -5e-6);  // 5 um radial play
  EXPECT_EQ(Evaluate(model, 0.0, 10.0, Eigen::Vector2d(0.0, 4.9e-6)).force.norm(), 0.0);
  const Wrench w = Evaluate(model, 0.0, 10.0, Eigen::Vector2d(0.0, 6e-6));
  EXPECT_LT(w.force.z(), 0.0);
  EXPECT_LT(w.torque.y(), 0.0);
}

TEST(KnuckleBearing, TurningTheBallInAPerfectSocketChangesNothingAtColumnSteps) {
  // Property over seeds: with a perfect socket, the interference volume of a lobed ball is the
  // same after a rotation by any whole number of column pitches.
  PartSpec ball = test::Ball();
  ball.form.tolerance[FormCharacteristic::kRoundness] = 2e-6;
  int changed_between_columns = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Model model;
    Prepare(&model, ball, test::Socket(), Resolution{10, 36}, 1e-6, seed, 4e-6);
    ContactState at_rest, turned, between;
    Evaluate(model, 0.0, 0.0, Eigen::Vector2d::Zero(), &at_rest);
    ASSERT_GT(at_rest.interference_volume, 0.0) << seed;
    Evaluate(model, 7 * 2.0 * M_PI / 36, 0.0, Eigen::Vector2d::Zero(), &turned);
    EXPECT_NEAR(turned.interference_volume, at_rest.interference_volume,
                1e-12 * at_rest.interference_volume)
        << seed;
    Evaluate(model, 7.5 * 2.0 * M_PI / 36, 0.0, Eigen::Vector2d::Zero(), &between);
    EXPECT_TRUE(std::isfinite(between.interference_volume));
    // Half a pitch off the columns the lobes sit elsewhere on the perfect socket: partial contact
    // changes, which proves the ball has form and the rotation reaches it.
    if (std::abs(between.interference_volume - at_rest.interference_volume) >
        1e-6 * at_rest.interference_volume) {
      ++changed_between_columns;
    }
  }
  // (5 of these 20 seeds: in the others every cell is in contact, and a Winkler sum over a perfect
  // socket is the same at any angle.)
  EXPECT_GE(changed_between_columns, 3);
}

}  // namespace
}  // namespace fitfeel::spherical

namespace fitfeel::spherical {
namespace {

TEST(KnuckleTexture, ExpectedInterferenceIsTheTruncatedGaussianOracle) {
  // Only the socket is rough (Rz = 6 um: sigma = 1 um, limits +-3 sigma, docs/oracles.md's
  // truncated N(0,1)); a ball of actual size nominal - 2 g um leaves the uniform gap g.
  PartSpec socket = test::Socket();
  socket.texture.rz = 6e-6;
  const double table[][2] = {{-1.0, 1.080451}, {0.0, 0.395578}, {1.0, 0.080451}, {2.0, 0.006777}};
  for (const auto& [g, expected] : table) {
    PartSpec ball = test::Ball();
    ball.size.lower_deviation = ball.size.upper_deviation = -2.0 * g * 1e-6;
    ModelSettings settings;
    settings.friction = kMu;
    settings.contact_stiffness = 1e6;
    settings.texture = TextureMode::kExpected;
    const Resolution r{10, 36};
    Rng rng(1);
    const SphericalDiscretizer discretizer;
    const SphericalVariationGenerator generator;
    const SkinModelShape ball_sms =
        generator.Generate(ball, discretizer.Discretize(ball, r), TextureMode::kExpected, rng);
    const SkinModelShape socket_sms =
        generator.Generate(socket, discretizer.Discretize(socket, r), TextureMode::kExpected, rng);
    SphericalContactAnalyzer analyzer;
    analyzer.Prepare(ball, ball_sms, socket, socket_sms, settings);
    ContactState contact;
    analyzer.scan().Evaluate(MatingPose{}, &contact);
    EXPECT_NEAR(contact.interference_volume / (2.0 * M_PI * kA * kB), expected * 1e-6, 2e-12) << g;
    // The tabulated analyzer at a rotation step, within its stated interpolation bound.
    ContactState tabulated;
    analyzer.Evaluate(MatingPose{}, &tabulated);
    double bound = 0.0;
    for (int j = 0; j < analyzer.table().columns(); ++j) {
      bound += analyzer.table().VolumeErrorBound(0, j);
    }
    EXPECT_NEAR(tabulated.interference_volume, contact.interference_volume, bound) << g;
    EXPECT_LT(bound, 0.05 * 1e-6 * 2.0 * M_PI * kA * kB) << g;
  }
}

}  // namespace
}  // namespace fitfeel::spherical

namespace fitfeel::spherical {
namespace {

TEST(KnuckleBearing, TorqueIsContinuousInTheAngleForAnyForm) {
  // Property over seeds: a lobed ball in a socket with sphericity error, turned through a full
  // revolution under a radial offset: the torque has no step (jumps shrink with the sample step).
  // Partial contact on purpose: with every cell in contact the Winkler sum is invariant under the
  // rotation (the interpolated ball sums to the same), and the torque would be constant.
  PartSpec ball = test::Ball();
  PartSpec socket = test::Socket();
  ball.form.tolerance[FormCharacteristic::kRoundness] = 4e-6;
  socket.form.tolerance[FormCharacteristic::kSphericity] = 6e-6;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Model model;
    Prepare(&model, ball, socket, Resolution{10, 36}, 0.2e-6, seed, 10e-6);
    const auto largest_jump = [&](int samples) {
      double largest = 0.0, previous = 0.0;
      for (int k = 0; k <= samples; ++k) {
        const double t =
            Evaluate(model, 2.0 * M_PI * k / samples, 10.0, Eigen::Vector2d(0.0, 6e-6)).torque.y();
        if (k > 0) largest = std::max(largest, std::abs(t - previous));
        previous = t;
      }
      return largest;
    };
    const double coarse = largest_jump(2000), fine = largest_jump(8000);
    EXPECT_GT(coarse, 0.0) << seed;
    EXPECT_LE(fine, 0.5 * coarse) << seed;
  }
}

}  // namespace
}  // namespace fitfeel::spherical

namespace fitfeel::spherical {
namespace {

TEST(KnuckleBearing, NonFinitePosesGiveNoContact) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{8, 8}, 1e-6);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Wrench a = Evaluate(model, nan, 10.0);
  const Wrench b = Evaluate(model, 0.0, 10.0, Eigen::Vector2d(0.0, nan));
  EXPECT_TRUE(a.AllFinite() && b.AllFinite());
  EXPECT_EQ(a.force.norm() + a.torque.norm() + b.force.norm() + b.torque.norm(), 0.0);
}

}  // namespace
}  // namespace fitfeel::spherical

namespace fitfeel::spherical {
namespace {

TEST(KnuckleBearing, RadialSupportGrowsMonotonicallyWithOffsetForAnyForm) {
  // The constrained stage settles the ball under its radial load by bracketing the root of the
  // support along the load: -F . u must be non-decreasing in the offset s along u (each socket
  // cell adds P delta_k (n_k . u), delta_k non-decreasing in s (n_k . u)). Over seeds, angles and
  // directions, with a 20 um play and 9 um of sphericity on both.
  PartSpec ball = test::Ball();
  PartSpec socket = test::Socket();
  ball.form.tolerance[FormCharacteristic::kSphericity] = 9e-6;
  socket.form.tolerance[FormCharacteristic::kSphericity] = 9e-6;
  int rising = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Model model;
    Prepare(&model, ball, socket, Resolution{8, 72}, -10e-6, seed, 20e-6);
    for (double angle : {0.0, 0.3, -1.1}) {
      for (int d = 0; d < 8; ++d) {
        const Eigen::Vector2d u(std::cos(d * M_PI / 4 + 0.1), std::sin(d * M_PI / 4 + 0.1));
        double previous = -std::numeric_limits<double>::infinity();
        for (double s = -60e-6; s <= 60e-6; s += 0.5e-6) {
          const double support =
              -Evaluate(model, angle, 0.0, s * u).force.dot(Eigen::Vector3d(u.x(), 0.0, u.y()));
          ASSERT_GE(support, previous - 1e-9 * std::abs(previous)) << seed << " " << s;
          if (support > previous + 1.0) ++rising;
          previous = support;
        }
      }
    }
  }
  EXPECT_GT(rising, 500);
}

// The GE 20 E outer ring (dk 29 mm, D 35 mm) is a ring, not a shell: Lame's
// cylinder gives 2.270 MPa/um, the thick shell (a 14.5 mm, b 17.5 mm) 5.947, 2.62 times stiffer.
TEST(KnuckleBearing, RingOfTheBearingIsSofterThanTheShell) {
  const Material steel = test::Steel();
  const double ring = RingPressurePerInterference(29e-3, 35e-3, steel, steel);
  const double shell = ThickShellPressurePerInterference(14.5e-3, 17.5e-3, steel, steel);
  EXPECT_NEAR(ring * 1e-12, 2.2700, 0.0005);
  EXPECT_NEAR(shell * 1e-12, 5.9470, 0.0005);
  EXPECT_NEAR(shell / ring, 2.620, 0.001);
}

// The GE 20 E outer ring's band (C = 12 mm) slice by slice, solid ball and the inner ring's 20 mm
// bore, against the independent midpoint sums: 2.720 and 1.980 MPa/um (the equator's 2.270 and
// 1.767).
TEST(KnuckleBearing, BandCoefficientOfGe20EWithAndWithoutTheInnerRingsBore) {
  const Material steel = test::Steel();
  const double solid = BandPressurePerInterference(29e-3, 12e-3, 35e-3, 0.0, steel, steel);
  const double bored = BandPressurePerInterference(29e-3, 12e-3, 35e-3, 20e-3, steel, steel);
  EXPECT_NEAR(solid, BandCoefficient(14.5e-3, 12e-3, 35e-3), 1e-8 * solid);
  EXPECT_NEAR(bored, BandCoefficient(14.5e-3, 12e-3, 35e-3, 20e-3), 1e-8 * bored);
  EXPECT_NEAR(solid * 1e-12, 2.7199, 0.0005);
  EXPECT_NEAR(bored * 1e-12, 1.9804, 0.0005);
  EXPECT_NEAR(RingPressurePerInterference(29e-3, 35e-3, steel, steel, 20e-3) * 1e-12, 1.7674,
              0.0005);
  EXPECT_THROW(BandPressurePerInterference(29e-3, 12e-3, 35e-3, 27e-3, steel, steel), UserError);
}

// tools/fem/data/axisymmetric.csv (AxisymmetricFemForce): CalculiX, GE 20 E in axisymmetry (the
// ball's 16 mm band in the ring's 12 mm one, 1 um radial interference), its bursting force B =
// integral of p n_r dA. The model's pressure is P_band * delta on every socket cell, so its B is
// the normal force from the analyzer and law times rho / a (n_r = cos(latitude), rho the band's
// mean axis distance).
TEST(KnuckleBearing, RingBandAgreesWithCalculixWithinTenPercent) {
  for (const double bore : {0.0, 20e-3}) {
    PartSpec ball = test::Ball(16e-3), socket = test::Socket(12e-3, 35e-3);
    ball.size.nominal = socket.size.nominal = 29e-3;
    ball.geometry = std::make_shared<SphericalGeometry>(Role::kInner, 29e-3, 16e-3, 0.0, bore);
    socket.geometry = std::make_shared<SphericalGeometry>(Role::kOuter, 29e-3, 12e-3, 35e-3);
    Model model;
    Prepare(&model, ball, socket, Resolution{24, 72}, 1e-6);
    ContactState contact;
    Evaluate(model, 0.0, 0.0, Eigen::Vector2d::Zero(), &contact);
    const double normal = model.law.pressure_per_interference() * contact.interference_volume;
    const double a = 14.5e-3, rho = GeometryOf(socket).mean_axis_distance();
    const double model_b = normal * rho / a;
    const double fem = test_support::AxisymmetricFemForce(bore > 0.0 ? "ball-bore" : "ball-solid");
    // The equator's Lame ring, what the law used before the band's slices.
    const double equator = RingPressurePerInterference(29e-3, 35e-3, test::Steel(), test::Steel()) *
                           contact.interference_volume * rho / a;
    std::printf(
        "bore %.0f mm: FEM %.1f N, band slices %.1f N (%+.1f %%), equator ring %.1f N "
        "(%+.1f %%)\n",
        bore * 1e3, fem, model_b, 100 * (model_b / fem - 1), equator, 100 * (equator / fem - 1));
    EXPECT_LT(std::abs(model_b / fem - 1.0), 0.10) << "bore " << bore;
  }
}

// Conformal Hertz (Johnson 1985, 4.2) with independent numbers: R1 = 10 mm, c = 30 um, so
// R = 10 * 10.03 / 0.03 mm = 3.3433 m; E* = E / (2 (1 - nu^2)) = 115.38 GPa; at delta = 1 um:
// W = 4/3 E* sqrt(R) delta^1.5 = 281.3 N, a = sqrt(R delta) = 1.828 mm, p0 = 3W/(2 pi a^2)
// = 40.2 MPa.
TEST(KnuckleBearing, ConformalHertzClosedForm) {
  const Material steel = test::Steel();
  const double e_star = ContactModulus(steel, steel);
  EXPECT_NEAR(e_star * 1e-9, 115.38, 0.01);
  const HertzContact h = ConformalHertz(10e-3, 30e-6, 1e-6, e_star);
  EXPECT_NEAR(h.load, 281.3, 0.1);
  EXPECT_NEAR(h.radius * 1e3, 1.8285, 0.0005);
  EXPECT_NEAR(h.peak_pressure * 1e-6, 40.17, 0.02);
  EXPECT_EQ(ConformalHertz(10e-3, 0.0, 1e-6, e_star).load, 0.0);  // no clearance: not local
  // W grows as delta^1.5.
  EXPECT_NEAR(ConformalHertz(10e-3, 30e-6, 4e-6, e_star).load / h.load, 8.0, 1e-12);
}

// tools/fem/data/bearing.csv: CalculiX in 3-D (tools/fem/solid.py), GE 20 E loaded across a
// radial clearance of 30 um, its outer ring held in a rigid housing, its inner ring held on a
// rigid shaft moved by the clearance plus the approach; the FEM's radial load against the law's
// local contact (its rings' walls, 4.5 and 2.97 mm at the equator, as layers bonded to their
// supports; the gap's curvature R = R1 R2 / (c + delta), held beyond a = 0.3 R1) at 1, 2 and 3 um
// of approach, within 10 %; the same geometry with half-spaces (Hertz) is 50 to 70 %
// soft.
TEST(KnuckleBearing, LoadedBearingAgreesWithCalculix) {
  const double e_star = ContactModulus(test::Steel(), test::Steel());
  const LayeredConformalContact walls(14.5e-3, {test::Steel(), 4.5e-3}, {test::Steel(), 2.97e-3});
  for (const char* name :
       {"bearing-approach-1um", "bearing-approach-2um", "bearing-approach-3um"}) {
    const double clearance = test_support::FemValue("bearing.csv", name, 1) * 1e-6;
    const double approach = test_support::FemValue("bearing.csv", name, 2) * 1e-6;
    const double fem = test_support::FemValue("bearing.csv", name, 3);
    const double hertz = LocalContact(14.5e-3, clearance, approach, e_star).load;
    const double law = walls.Load(clearance, approach).load;
    std::printf(
        "%-22s FEM %7.1f N  walls %7.1f N %+5.1f %%  half-spaces (Hertz) %7.1f N %+5.1f %%\n", name,
        fem, law, 100 * (law / fem - 1), hertz, 100 * (hertz / fem - 1));
    EXPECT_LT(std::abs(law / fem - 1), 0.10) << name;
    EXPECT_LT(hertz / fem, 0.5) << name;
  }
}

// The law on a loaded bearing: 30 um radial play, the ball pushed 31 um off centre, so its
// approach is 1 um over a patch of a / R1 = 0.18: the local contact alone carries it, conformal
// Hertz (281.3 N) stiffened by the socket's 5 mm wall on its housing (the solid ball is a
// half-space), back along the offset, and the friction torque is mu W rho while turning.
TEST(KnuckleBearing, LoadedPlainBearingIsALocalContact) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{40, 360}, -30e-6);
  ContactState contact;
  const Wrench w = Evaluate(model, 0.0, 10.0, Eigen::Vector2d(0.0, -31e-6), &contact);
  // Cell centres sit half a column (0.5 deg) and half a row off the load line: delta = 0.999 um.
  EXPECT_NEAR(contact.max_interference, 1e-6, 3e-9);
  const double clearance = 31e-6 - contact.max_interference;
  const double hertz = ConformalHertz(10e-3, clearance, contact.max_interference,
                                      ContactModulus(test::Steel(), test::Steel()))
                           .load;
  EXPECT_NEAR(hertz, 281.3, 1.5);
  const LayeredConformalContact walls(10e-3, {test::Steel()}, {test::Steel(), 5e-3});
  const double load = walls.Load(clearance, contact.max_interference).load;
  EXPECT_GT(load, 1.05 * hertz);
  EXPECT_LT(load, 1.5 * hertz);
  EXPECT_NEAR(w.force.norm(), load, 1e-9 * load);
  EXPECT_NEAR(w.force.z(), load, 1e-3 * load);  // along the offset, back
  EXPECT_NEAR(w.torque.y(), -kMu * load * model.law.friction_arm(), 1e-9 * load);
  // The per-cell ring bed would carry it far softer (the ring's breathing is not a local patch).
  EXPECT_LT(model.law.pressure_per_interference() * contact.pressure_resultant.norm(), 0.8 * 281.3);
  // The local load is not a linear map of the resultant: no stiffness in closed form there.
  Eigen::Matrix2d jacobian;
  EXPECT_FALSE(model.law.RadialJacobian(contact, &jacobian));
}

// Interfering all round (1 um, the ring's bed carries it), the law's radial stiffness in closed
// form is -P times the table's resultant Jacobian: against central differences of the radial
// force over 1 pm in both directions of the offset.
TEST(KnuckleBearing, TheRingsBedGivesItsStiffnessInClosedForm) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{20, 72}, 1e-6);
  const Eigen::Vector2d offset(0.13e-6, -0.21e-6);
  ContactState contact;
  Evaluate(model, 0.0, 10.0, offset, &contact);
  Eigen::Matrix2d jacobian;
  ASSERT_TRUE(model.law.RadialJacobian(contact, &jacobian));
  constexpr double h = 1e-12;
  for (int axis = 0; axis < 2; ++axis) {
    ContactState unused;
    const Wrench plus =
        Evaluate(model, 0.0, 10.0, offset + h * Eigen::Vector2d::Unit(axis), &unused);
    const Wrench minus =
        Evaluate(model, 0.0, 10.0, offset - h * Eigen::Vector2d::Unit(axis), &unused);
    const Eigen::Vector2d numeric = (Eigen::Vector2d(plus.force.x(), plus.force.z()) -
                                     Eigen::Vector2d(minus.force.x(), minus.force.z())) /
                                    (2.0 * h);
    EXPECT_LT((numeric - jacobian.col(axis)).norm(), 1e-5 * jacobian.norm()) << axis;
  }
}

// Stick-slip torque: a ball held still under load does not turn below mu_s N rho, and turns at
// mu_k N rho (the run's state, framework/model/friction.h).
TEST(KnuckleBearing, StickSlipTorqueWithTheRunsState) {
  Model model;
  Prepare(&model, test::Ball(), test::Socket(), Resolution{20, 72}, 1e-6);
  MatingPose pose;
  ContactState contact;
  model.analyzer.Evaluate(pose, &contact);
  const double normal = model.law.pressure_per_interference() * contact.interference_volume;
  const double rho = model.law.friction_arm();
  LawState state;
  MatingMotion motion;
  Wrench w;
  for (double angle = 0.0; angle < 1e-3; angle += 1e-4) {  // turning: 1.4 um of arc per step
    motion.angle = angle;
    model.law.Evaluate(contact, motion, &state, &w);
  }
  EXPECT_NEAR(w.torque.y(), -kMu * normal * rho, 1e-9 * normal * rho);
  // Held: a tiny turn back unloads the junctions, the ball sticks (no slip).
  motion.angle -= 0.2e-4;
  model.law.Evaluate(contact, motion, &state, &w);
  EXPECT_FALSE(state.friction.sliding);
  EXPECT_GT(w.torque.y(), -kMu * normal * rho);
}

}  // namespace
}  // namespace fitfeel::spherical
