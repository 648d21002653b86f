// The positioning stage with coarse meshes: FCL contact in free motion, the hand-over, and a tick
// that does not allocate.
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "framework/collision/coarse_mesh.h"
#include "framework/core/error.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/testing/allocation_counter.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

constexpr double kRadius = 10e-3;     // 20 mm fit
constexpr double kHubRadius = 15e-3;  // 30 mm hub
constexpr double kStiffness = 2e3;    // N/m: a PHANTOM-class stable stiffness
constexpr int kFacets = 50;           // the paper pair's count (cylindrical CoarseFacets)

CoarseMeshes Meshes() {
  CoarseMeshes m;
  m.inner = MakeClosedCylinder(kRadius, -60e-3, 0.0, kFacets);
  m.outer = MakeTube(kRadius, kHubRadius, 0.0, 20e-3, kFacets);
  return m;
}

PositioningStage::Options WithStiffness(double k = kStiffness) {
  PositioningStage::Options o;
  o.free_stiffness = k;
  return o;
}

PartState At(double x, double y, double z, double tilt_about_z = 0.0) {
  PartState s;
  s.position = Eigen::Vector3d(x, y, z);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(tilt_about_z, Eigen::Vector3d::UnitZ()));
  return s;
}

TEST(PositioningCollisionTest, FarAwayIsFreeAndRendersNothing) {
  const PositioningStage stage(WithStiffness(), Meshes(), Role::kInner);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  ASSERT_TRUE(stage.collides());
  StageOutput out;
  out.wrench.force.setConstant(7.0);
  for (const PartState& s : {At(0.0, -10e-3, 0.0), At(40e-3, 5e-3, 0.0), At(3e-3, -1e-6, 0.0)}) {
    stage.Evaluate(s, stage_run.get(), &out);
    EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
    EXPECT_EQ(out.wrench.torque, Eigen::Vector3d::Zero());
    EXPECT_EQ(out.stiffness, 0.0);
    EXPECT_EQ(out.next, StageId::kPositioning);
  }
}

// An off-axis shaft end on the bushing's annular face: a flat end on a flat face, so FCL's depth
// is the leading end's y exactly (no chordal error along y); the force is k * depth along -y.
TEST(PositioningCollisionTest, AnOffAxisEndOnTheFaceIsPushedBackAlongMinusY) {
  const PositioningStage stage(WithStiffness(), Meshes(), Role::kInner);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  const double chordal = ChordalError(kRadius, kFacets);
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 gen(seed);
    // Offsets past the capture radius, up to where the end disc still overlaps the hub's face.
    std::uniform_real_distribution<double> radial(1e-3, kRadius + kHubRadius - 1e-3);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    std::uniform_real_distribution<double> depth(1e-6, 1e-3);
    for (int i = 0; i < 10; ++i) {
      const double r = radial(gen), a = angle(gen), y = depth(gen);
      StageOutput out;
      stage.Evaluate(At(r * std::cos(a), y, r * std::sin(a)), stage_run.get(), &out);
      EXPECT_EQ(out.next, StageId::kPositioning);
      ASSERT_LT(out.wrench.force.y(), 0.0) << "seed " << seed << " r " << r << " y " << y;
      EXPECT_NEAR(out.wrench.force.y(), -kStiffness * y, kStiffness * chordal);
      EXPECT_NEAR(out.wrench.force.y(), -kStiffness * y, 1e-9 * kStiffness * y);
      EXPECT_NEAR(out.wrench.force.x(), 0.0, 1e-12);
      EXPECT_NEAR(out.wrench.force.z(), 0.0, 1e-12);
      EXPECT_EQ(out.stiffness, kStiffness);
      // A force along y applied on the end face has no moment about y.
      EXPECT_NEAR(out.wrench.torque.y(), 0.0, 1e-12);
    }
  }
}

TEST(PositioningCollisionTest, ACentredShaftPassesTheEntranceAndIsHandedOver) {
  const PositioningStage stage(WithStiffness(), Meshes(), Role::kInner);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  for (double y : {-1e-3, -1e-9, 0.0, 1e-6, 1e-3}) {
    stage.Evaluate(At(0.0, y, 0.0), stage_run.get(), &out);
    EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero()) << y;
    EXPECT_EQ(out.next, y >= 0.0 ? StageId::kConstrained : StageId::kPositioning);
  }
  // With no alignment tolerance, a slightly tilted shaft stays in free motion inside the bore:
  // the coarse meshes must not collide there (10 urad over 10 mm is 0.1 um, well inside the
  // meshes' chordal slack of ~20 um), so the stage still renders nothing.
  PositioningStage::Options strict = WithStiffness();
  strict.alignment_tolerance = 0.0;
  const PositioningStage strict_stage(strict, Meshes(), Role::kInner);
  const std::unique_ptr<StageState> strict_stage_run = strict_stage.MakeState();
  for (double y : {0.0, 1e-3, 10e-3, 19e-3}) {
    strict_stage.Evaluate(At(0.0, y, 0.0, 1e-5), strict_stage_run.get(), &out);
    EXPECT_EQ(out.next, StageId::kPositioning);
    EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero()) << y;
  }
  // The same strict stage does feel a shaft off by more than the slack: the walls collide.
  strict_stage.Evaluate(At(0.2e-3, 10e-3, 0.0, 1e-5), strict_stage_run.get(), &out);
  EXPECT_GT(out.wrench.force.norm(), 0.0);
  EXPECT_LT(out.wrench.force.x(), 0.0);  // pushed back towards the axis
}

// A bushing slid over a fixed shaft: the meshes are turned half a turn about z, the shaft's end
// sits at the entrance and the bushing's face strikes it when the bushing is off-axis.
TEST(PositioningCollisionTest, AMovingBushingStrikesTheShaftsEnd) {
  const PositioningStage stage(WithStiffness(), Meshes(), Role::kOuter);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  stage.Evaluate(At(0.0, 5e-3, 0.0), stage_run.get(), &out);  // centred: the shaft is inside the bore
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  stage.Evaluate(At(15e-3, -1e-3, 0.0), stage_run.get(), &out);  // in front of the shaft's end
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  const double y = 3e-4;
  stage.Evaluate(At(15e-3, y, 0.0), stage_run.get(), &out);
  EXPECT_NEAR(out.wrench.force.y(), -kStiffness * y, 1e-9 * kStiffness * y);
}

// With a lead-in the bushing slid over the shaft goes through the funnel the shaft pushed into
// the bushing meets (the free region is one of relative position): on the same device path
// (onto the chamfers off the axis, down them, into the bore and out again) the stage answers
// both roles alike, tick by tick, and pushes the part back and towards the axis on the chamfer,
// where the meshes alone would have had FCL's answer for the bushing.
TEST(PositioningCollisionTest, WithALeadInEitherPartMovesThroughTheSameFunnel) {
  RadiusProfile shaft, bore;
  shaft.points = {{0.0, kRadius - 0.5e-3}, {0.5e-3, kRadius}};     // C0.5 end
  bore.points = {{0.0, kRadius + 1e-3}, {1e-3, kRadius + 10e-6}};  // C1 entrance, 10 um play
  const LeadIn lead_in(shaft, bore, -1e-3, 0.5e-3);
  const PositioningStage inner(WithStiffness(), Meshes(), Role::kInner, lead_in);
  const PositioningStage outer(WithStiffness(), Meshes(), Role::kOuter, lead_in);
  const std::unique_ptr<StageState> inner_run = inner.MakeState(), outer_run = outer.MakeState();
  EXPECT_TRUE(outer.collides());
  EXPECT_EQ(outer.depth_origin(), inner.depth_origin());
  bool pushed_back = false;
  for (int i = 0; i <= 400; ++i) {
    // 1.2 mm off along x and 0.3 mm along z, from 3 mm in front of the entrance to 1 mm past
    // the capture depth and back: the part lands on the chamfer and slides down it.
    const double s = i <= 200 ? i / 200.0 : (400 - i) / 200.0;
    const PartState device = At(1.2e-3, -3e-3 + 4e-3 * s, 0.3e-3);
    StageOutput a, b;
    inner.Evaluate(device, inner_run.get(), &a);
    outer.Evaluate(device, outer_run.get(), &b);
    ASSERT_EQ(a.wrench.force, b.wrench.force) << i;
    ASSERT_EQ(a.pose.depth, b.pose.depth) << i;
    ASSERT_EQ(a.pose.offset, b.pose.offset) << i;
    ASSERT_EQ(a.next, b.next) << i;
    if (b.wrench.force.y() < 0.0 && b.wrench.force.x() < 0.0 && b.wrench.force.z() < 0.0) {
      pushed_back = true;
    }
  }
  EXPECT_TRUE(pushed_back);
}

TEST(PositioningCollisionTest, WithoutMeshesFreeMotionIsCollisionFree) {
  const PositioningStage stage(WithStiffness(), CoarseMeshes{}, Role::kInner);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  EXPECT_FALSE(stage.collides());
  StageOutput out;
  stage.Evaluate(At(5e-3, 1e-3, 0.0), stage_run.get(), &out);
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
}

TEST(PositioningCollisionTest, FreeStiffnessIsTheContactStiffnessCappedByTheDevice) {
  EXPECT_EQ(FreeMotionStiffness(2e6, 1.5e3), 1.5e3);
  EXPECT_EQ(FreeMotionStiffness(1e3, 1.5e3), 1e3);
  EXPECT_EQ(FreeMotionStiffness(2e6, 0.0), 2e6);  // device states no limit
  EXPECT_EQ(FreeMotionStiffness(2e6, std::numeric_limits<double>::infinity()), 2e6);
  EXPECT_EQ(FreeMotionStiffness(0.0, 1.5e3), 1.5e3);  // `auto`: the device's own limit
  EXPECT_EQ(FreeMotionStiffness(0.0, std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_THROW(FreeMotionStiffness(std::numeric_limits<double>::infinity(), 0.0), UserError);
  EXPECT_THROW(FreeMotionStiffness(-1.0, 0.0), UserError);
  EXPECT_THROW(FreeMotionStiffness(1.0, std::nan("")), UserError);
  PositioningStage::Options o;
  o.free_stiffness = -1.0;
  EXPECT_THROW(PositioningStage{o}, UserError);
  o = {};
  o.max_contacts = 0;
  EXPECT_THROW(PositioningStage(o, Meshes(), Role::kInner), UserError);
}

TEST(PositioningCollisionTest, CounterSeesAllocations) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  auto probe = std::make_unique<double>(1.0);
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 1);
}

// The tick's FCL query reuses the contact buffer reserved at construction: no operator new,
// whether free, striking the face, or handed over.
TEST(PositioningCollisionTest, TheTickDoesNotAllocate) {
  const PositioningStage stage(WithStiffness(), Meshes(), Role::kInner);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  int in_contact = 0;
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  for (int k = 0; k < 3000; ++k) {
    const double x = 15e-3 * std::sin(k * 0.01);
    const double y = 2e-3 * std::cos(k * 0.013);
    stage.Evaluate(At(x, y, 0.3 * x, 0.02 * std::sin(k * 0.007)), stage_run.get(), &out);
    in_contact += out.stiffness > 0.0 ? 1 : 0;
  }
  allocations.Stop();
  EXPECT_GT(in_contact, 100);
  EXPECT_LT(in_contact, 2900);
  EXPECT_EQ(allocations.count(), 0);
}

}  // namespace
}  // namespace fitfeel
