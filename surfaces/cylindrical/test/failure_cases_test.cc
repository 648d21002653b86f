// Where the paper's own model could fail: an assembly space that is empty everywhere, a bushing
// whose wall thins to nothing (d2 -> d1), a contact with exactly zero clearance, and a shaft that
// leaves the bore (through its far end, and backwards out of its entrance) and comes back. Through
// the real analyzer and the gps law, with synthetic skin model shapes: every force must be finite,
// and continuous, which a sampled sweep shows when halving the step halves the largest change
// between samples.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using namespace testing;
constexpr double kSpeed = 0.010;  // m/s, the paper's insertion speed (4.1)

struct Joint {
  PartSpec shaft = MakeShaft(0.020, 0.040);
  PartSpec bushing = MakeBushing(0.020, 0.020, 0.030);
  CylinderContactAnalyzer analyzer;
  GpsLaw law;

  Joint(const std::function<double(int, int)>& shaft_v,
        const std::function<double(int, int)>& bushing_v, double kp, bool texture = false,
        double outer_diameter = 0.030) {
    bushing = MakeBushing(0.020, 0.020, outer_diameter);
    if (texture) {
      const TextureSpec t{3.2 * kUm, 0.4 * kUm, 1.6 * kUm};  // paper Table 2
      shaft.texture = t;
      bushing.texture = t;
    }
    analyzer.Prepare(shaft, MakeSms(MakeGrid(40, 36, 0.020, 0.040), shaft_v), bushing,
                     MakeSms(MakeGrid(20, 36, 0.020, 0.020), bushing_v),
                     Settings(0.15, kp, texture ? TextureMode::kExpected : TextureMode::kSampled));
    law.Prepare(shaft, bushing, Settings(0.15, kp));
  }

  Wrench At(double depth, const Eigen::Vector2d& offset, double velocity,
            ContactState* state = nullptr) const {
    MatingPose pose;
    pose.depth = depth;
    pose.offset = offset;
    ContactState s;
    analyzer.Evaluate(pose, &s);
    MatingMotion motion;
    motion.velocity.y() = velocity;
    Wrench w;
    law.Evaluate(s, motion, &w);
    if (state != nullptr) *state = s;
    return w;
  }
};

struct Sweep {
  double largest_jump = 0.0;   // N, largest change of the force between consecutive samples
  double largest_force = 0.0;  // N
  bool all_finite = true;
  int interfering = 0;  // samples with an empty assembly space
  int engaged = 0;
};

// Samples the force from `from` to `to` (either direction) every `step`, moving that way at the
// paper's speed.
Sweep SweepDepth(const Joint& joint, double from, double to, double step,
                 const Eigen::Vector2d& offset) {
  Sweep out;
  const double direction = to > from ? 1.0 : -1.0;
  const int samples = static_cast<int>(std::llround(std::abs(to - from) / step));
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (int i = 0; i <= samples; ++i) {
    const double depth = from + direction * step * i;
    ContactState s;
    const Wrench w = joint.At(depth, offset, direction * kSpeed, &s);
    if (!w.AllFinite() || !std::isfinite(s.interference_volume) || !std::isfinite(s.penetration)) {
      out.all_finite = false;
      continue;
    }
    if (i > 0) out.largest_jump = std::max(out.largest_jump, (w.force - previous).norm());
    out.largest_force = std::max(out.largest_force, w.force.norm());
    out.interfering += s.interference ? 1 : 0;
    out.engaged += s.engaged ? 1 : 0;
    previous = w.force;
  }
  return out;
}

// The sweep is continuous at this resolution when halving the step twice halves the largest jump
// each time (a jump in the force would stay the same size however fine the sampling).
void ExpectContinuous(const Joint& joint, double from, double to, const Eigen::Vector2d& offset,
                      const char* what) {
  const double coarse_step = joint.analyzer.depth_step() / 20.0;
  const Sweep coarse = SweepDepth(joint, from, to, coarse_step, offset);
  const Sweep medium = SweepDepth(joint, from, to, coarse_step / 2.0, offset);
  const Sweep fine = SweepDepth(joint, from, to, coarse_step / 4.0, offset);
  EXPECT_TRUE(coarse.all_finite && medium.all_finite && fine.all_finite) << what;
  EXPECT_GT(coarse.largest_jump, 0.0) << what;
  EXPECT_LT(medium.largest_jump, 0.6 * coarse.largest_jump) << what;
  EXPECT_LT(fine.largest_jump, 0.6 * medium.largest_jump) << what;
}

// Assembly space empty at every engaged depth: the shaft is 3 um (radius) larger than the bore
// everywhere, plus an oval and a lobed form, so the energy-minimising axis has to be found.
TEST(FailureCases, EmptyAssemblySpaceEverywhere) {
  const Joint joint(
      [](int i, int j) {
        return (3.0 + 1.0 * std::cos(2.0 * j * 2.0 * std::numbers::pi / 36) +
                0.5 * std::sin(3.0 * j * 2.0 * std::numbers::pi / 36 + 0.1 * i)) *
               kUm;
      },
      [](int k, int j) { return 0.3 * std::cos(j + k) * kUm; }, 3.665e9);
  const double end = joint.analyzer.max_depth();
  const Sweep s = SweepDepth(joint, 0.0, end, joint.analyzer.depth_step() / 10.0, {0.0, 0.0});
  EXPECT_TRUE(s.all_finite);
  // Every engaged sample interferes, but for those within half a depth step of the entrance and
  // the exit, whose nearest tabulated step has no overlap yet.
  EXPECT_GT(s.engaged, 0);
  EXPECT_GE(s.interfering, s.engaged - 12);
  // Fully engaged (depth 20..40 mm), eq. 12: |F_y| = mu (|F_radial| + p' V) with the interference
  // volume V between the smallest (1.2 um) and the largest (4.8 um) radial interference times the
  // whole contact area, and p' V pi d1 L mu = 1099.6 N per um (docs/oracles.md).
  for (double depth = 20.5e-3; depth < 39.5e-3; depth += 1.3e-3) {
    const Wrench w = joint.At(depth, {0.0, 0.0}, kSpeed);
    const double radial = std::hypot(w.force.x(), w.force.z());
    const double lame = -w.force.y() - 0.15 * radial;
    EXPECT_GT(lame, 1.2 * 1099.6) << depth;
    EXPECT_LT(lame, 4.8 * 1099.6) << depth;
  }
  ExpectContinuous(joint, 0.0, end, {0.0, 0.0}, "empty AS, on the axis");
  ExpectContinuous(joint, 0.0, end, {2 * kUm, -1 * kUm}, "empty AS, off the axis");
  // With the paper's texture on both parts as well.
  const Joint rough([](int, int) { return 3.0 * kUm; }, [](int, int) { return 0.0; }, 3.665e9,
                    true);
  ExpectContinuous(rough, 0.0, end, {1 * kUm, 0.0}, "empty AS with texture");
  // Empty only where a 1 mm ring of the bore (rows 9 and 10) is 2 um tight, clear elsewhere: the
  // assembly space empties and reopens twice per pass.
  const Joint ring([](int, int) { return 0.0; },
                   [](int k, int) { return (k == 9 || k == 10 ? -2.0 : 3.0) * kUm; }, 3.665e9);
  const Sweep r = SweepDepth(ring, 0.0, end, ring.analyzer.depth_step() / 10.0, {0.0, 0.0});
  EXPECT_GT(r.interfering, 0);
  EXPECT_LT(r.interfering, r.engaged);
  ExpectContinuous(ring, 0.0, end, {0.5 * kUm, 0.0}, "tight ring");
}

// Thin-walled bushing: as d2 -> d1 the hub's compliance (d2^2 + d1^2) / (d2^2 - d1^2) grows
// without bound and the pressure per unit interference falls to zero, with no division blow-up
// even where d2^2 - d1^2 rounds to nothing. d2 <= d1 is refused.
TEST(FailureCases, ThinWalledBushingPressureFallsToZero) {
  const Material steel = Steel();
  double previous = std::numeric_limits<double>::infinity();
  for (double wall : {5e-3, 1e-3, 1e-4, 1e-6, 1e-9, 1e-12, 1e-15}) {
    const PressFitDimensions d{0.020, 0.020 + wall, 0.0};
    const double p = LamePressurePerInterference(d, steel, steel);
    EXPECT_TRUE(std::isfinite(p)) << wall;
    EXPECT_GE(p, 0.0) << wall;
    EXPECT_LT(p, previous) << wall;
    // Thin-wall limit: the hub's term ~ d1 / (wall E) dominates, p' -> 2 wall E / d1^2 (the
    // ring's hoop stiffness).
    if (wall <= 1e-6 && wall >= 1e-9) {
      EXPECT_NEAR(p, 2.0 * wall * steel.youngs_modulus / (0.020 * 0.020), 1e-3 * p);
    }
    previous = p;
  }
  // The last wall is below the rounding of d2^2 - d1^2 at 20 mm: d2 itself rounds onto d1.
  const PressFitDimensions touching{0.020, std::nextafter(0.020, 1.0), 0.0};
  const double p_touching = LamePressurePerInterference(touching, steel, steel);
  EXPECT_TRUE(std::isfinite(p_touching));
  EXPECT_LT(p_touching, 1e-2);

  // Through the analyzer and the law: forces shrink with the wall and stay finite.
  double previous_force = std::numeric_limits<double>::infinity();
  for (double wall : {10e-3, 1e-3, 1e-5, 1e-9}) {
    const Joint joint([](int, int) { return 2.0 * kUm; }, [](int, int) { return 0.0; }, 0.0, false,
                      0.020 + wall);
    const Sweep s = SweepDepth(joint, -1e-3, joint.analyzer.max_depth() + 1e-3,
                               joint.analyzer.depth_step() / 10.0, {1 * kUm, 0.0});
    EXPECT_TRUE(s.all_finite) << wall;
    EXPECT_LT(s.largest_force, previous_force) << wall;
    previous_force = s.largest_force;
  }
  EXPECT_LT(previous_force, 1e-3);  // a 1 nm wall carries next to nothing

  // A hub that does not surround the shaft is refused before any table is built.
  GpsLaw law;
  const PartSpec shaft = MakeShaft(0.020, 0.040);
  EXPECT_THROW(law.Prepare(shaft, MakeBushing(0.020, 0.020, 0.020), Settings(0.15)), UserError);
  EXPECT_THROW(law.Prepare(shaft, MakeBushing(0.020, 0.020, 0.019), Settings(0.15)), UserError);
}

// Zero clearance: bore and shaft coincide, the assembly space closes to a single point. The
// forces there must be the limit of the forces at a vanishing clearance and at a vanishing
// interference, from either side.
TEST(FailureCases, ZeroClearanceGrazingContact) {
  const double kp = 3.665e9;
  const Eigen::Vector2d offset(0.3 * kUm, -0.4 * kUm);  // 0.5 um off the axis
  const double depth = 30e-3;                           // fully engaged
  const Joint grazing([](int, int) { return 0.0; }, [](int, int) { return 0.0; }, kp);
  const Wrench at_zero = grazing.At(depth, offset, kSpeed);
  ASSERT_TRUE(at_zero.AllFinite());
  // The radial spring on the whole offset (the assembly space is the axis itself).
  EXPECT_NEAR(at_zero.force.x(), -kp * 0.3 * kUm, 1e-6 * kp * kUm);
  EXPECT_NEAR(at_zero.force.z(), kp * 0.4 * kUm, 1e-6 * kp * kUm);
  double previous_gap = std::numeric_limits<double>::infinity();
  for (double e : {1e-7, 1e-8, 1e-9, 1e-10}) {
    const Joint clearance([](int, int) { return 0.0; }, [=](int, int) { return e; }, kp);
    const Joint interference([=](int, int) { return e; }, [](int, int) { return 0.0; }, kp);
    const Wrench c = clearance.At(depth, offset, kSpeed);
    const Wrench i = interference.At(depth, offset, kSpeed);
    ASSERT_TRUE(c.AllFinite() && i.AllFinite()) << e;
    const double gap = std::max((c.force - at_zero.force).norm(), (i.force - at_zero.force).norm());
    // Linear in the clearance: k_p e radially, mu p' e pi d1 L axially.
    EXPECT_LT(gap, 2.0 * (kp + 0.15 * 1099.6e6) * e) << e;
    EXPECT_LT(gap, previous_gap) << e;
    previous_gap = gap;
  }
  // Grazing off the axis: a shaft of the bore's size whose surface is displaced by 2 um along x
  // (V = e cos(beta)) fits at exactly one axis position, (-e, 0): the assembly space is a point
  // away from the axis, whose opposite constraints meet exactly (or, after rounding, cross by an
  // ulp and read as interference). Either way the spring pulls towards that point, and a sweep of
  // the offset across it is continuous.
  const double e = 2 * kUm;
  const Joint shifted([=](int, int j) { return e * std::cos(2.0 * std::numbers::pi * j / 36); },
                      [](int, int) { return 0.0; }, kp);
  for (const Eigen::Vector2d& x :
       {Eigen::Vector2d(-e, 0.0), Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(-e, 0.5 * kUm)}) {
    const Wrench w = shifted.At(depth, x, kSpeed);
    ASSERT_TRUE(w.AllFinite());
    EXPECT_NEAR(w.force.x(), -kp * (x.x() + e), 1e-3 * kp * kUm) << x.transpose();
    EXPECT_NEAR(w.force.z(), -kp * x.y(), 1e-3 * kp * kUm) << x.transpose();
  }
  auto offset_jump = [&](double h) {
    double worst = 0.0;
    Eigen::Vector3d previous = shifted.At(depth, {-e - 0.5 * kUm, 0.1 * kUm}, kSpeed).force;
    for (double u = -e - 0.5 * kUm + h; u <= -e + 0.5 * kUm; u += h) {
      const Eigen::Vector3d f = shifted.At(depth, {u, 0.1 * kUm}, kSpeed).force;
      worst = std::max(worst, (f - previous).norm());
      previous = f;
    }
    return worst;
  };
  const double coarse = offset_jump(0.01 * kUm);
  EXPECT_GT(coarse, 0.0);
  EXPECT_LT(offset_jump(0.005 * kUm), 0.6 * coarse);
  ExpectContinuous(shifted, -1e-3, shifted.analyzer.max_depth() + 1e-3, {-e, 0.2 * kUm},
                   "grazing off the axis");
  // Along the insertion, grazing all the way.
  ExpectContinuous(grazing, -1e-3, grazing.analyzer.max_depth() + 1e-3, offset, "grazing");
}

// The shaft goes in, out through the bushing's far end (depth beyond L_shaft + L_bushing), back
// in, back out through the entrance (negative depth) and in again. Outside the bore no force;
// continuous through every transition; and the same force at the same depth and direction on
// every pass (the model has no memory).
TEST(FailureCases, ShaftLeavesAndReentersTheBore) {
  const Joint joint([](int i, int j) { return (-2.0 + 0.5 * std::cos(j + 0.3 * i)) * kUm; },
                    [](int k, int j) { return (1.0 + 0.8 * std::sin(2 * j + k)) * kUm; }, 3.665e9,
                    true);
  const double end = joint.analyzer.max_depth();
  const Eigen::Vector2d offset(4 * kUm, 1 * kUm);  // pressed against the bore: radial force
  for (double d :
       {-1e-3, -1e-9, 0.0, end, end + 1e-9, end + 1e-3, -1e3, 1e3,
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN()}) {
    const Wrench w = joint.At(d, offset, kSpeed);
    EXPECT_TRUE(w.AllFinite()) << d;
    EXPECT_EQ(w.force.norm(), 0.0) << d;
  }
  const double margin = 2e-3;
  const Sweep in =
      SweepDepth(joint, -margin, end + margin, joint.analyzer.depth_step() / 10.0, offset);
  EXPECT_GT(in.largest_force, 0.0);
  ExpectContinuous(joint, -margin, end + margin, offset, "in and out through the far end");
  ExpectContinuous(joint, end + margin, -margin, offset, "back and out through the entrance");
  // No memory: forward passes agree sample for sample, and so do backward passes.
  for (double d = -margin; d < end + margin; d += 0.37e-3) {
    const Wrench first = joint.At(d, offset, kSpeed);
    joint.At(end + margin, offset, kSpeed);
    joint.At(-margin, offset, -kSpeed);
    const Wrench again = joint.At(d, offset, kSpeed);
    EXPECT_EQ(first.force, again.force) << d;
    // Turning round changes only the sign of the friction; the radial force stays.
    const Wrench back = joint.At(d, offset, -kSpeed);
    EXPECT_NEAR(back.force.x(), first.force.x(), 1e-9 * (1.0 + std::abs(first.force.x())));
    EXPECT_NEAR(back.force.z(), first.force.z(), 1e-9 * (1.0 + std::abs(first.force.z())));
    EXPECT_NEAR(back.force.y(), -first.force.y(), 1e-9 * (1.0 + std::abs(first.force.y())));
  }
}

}  // namespace
}  // namespace fitfeel::cylindrical
