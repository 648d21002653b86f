
#include <cmath>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

#include "framework/core/error.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/test/fake_scene.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

PartState At(double x, double y, double z, double tilt_about_z = 0.0) {
  PartState s;
  s.position = Eigen::Vector3d(x, y, z);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(tilt_about_z, Eigen::Vector3d::UnitZ()));
  return s;
}

TEST(MatingPoseTest, DepthIsTheLeadingEndsYAndOffsetItsXZ) {
  PartState s = At(1e-5, 3e-3, -2e-5);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
  const MatingPose pose = MatingPoseOf(s);
  EXPECT_DOUBLE_EQ(pose.depth, 3e-3);
  EXPECT_DOUBLE_EQ(pose.offset.x(), 1e-5);
  EXPECT_DOUBLE_EQ(pose.offset.y(), -2e-5);
  EXPECT_NEAR(pose.angle, 0.3, 1e-12);
  // Twist about y is unaffected by a swing about another axis.
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitY())) *
                  Eigen::Quaterniond(Eigen::AngleAxisd(0.0, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(MatingPoseOf(s).angle, -0.5, 1e-12);
}

TEST(PositioningStageTest, RendersNothingAndHandsOverAtTheEntranceWhenAligned) {
  const PositioningStage stage;
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  out.wrench.force.setConstant(7.0);
  stage.Evaluate(At(0.0, -1e-6, 0.0), stage_run.get(), &out);
  EXPECT_EQ(out.wrench.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(out.next, StageId::kPositioning);
  stage.Evaluate(At(0.0, 0.0, 0.0), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kConstrained);
  stage.Evaluate(At(1e-4, 2e-3, -1e-4), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kConstrained);
}

// A state belongs to the stage that made it: another stage's (or none) is a caller's bug, caught
// in Release too.
TEST(StageStateDeathTest, EvaluateRefusesAStateOfAnotherStage) {
  const PositioningStage stage, other;
  const std::unique_ptr<StageState> foreign = other.MakeState();
  StageOutput out;
  EXPECT_EQ(foreign->owner(), &other);
  EXPECT_DEATH(stage.Evaluate(At(0.0, 0.0, 0.0), foreign.get(), &out), "demand failed: state");
  EXPECT_DEATH(stage.Evaluate(At(0.0, 0.0, 0.0), nullptr, &out), "demand failed: state");
}

TEST(PositioningStageTest, KeepsATiltedOrOffPart) {
  const PositioningStage stage;
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  const double tolerance = stage.options().alignment_tolerance;
  stage.Evaluate(At(0.0, 1e-3, 0.0, 0.99 * tolerance), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kConstrained);
  stage.Evaluate(At(0.0, 1e-3, 0.0, 1.01 * tolerance), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kPositioning);
  stage.Evaluate(At(0.0, 1e-3, -1.01 * stage.options().capture_radius), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kPositioning);
}

TEST(PositioningStageTest, RefusesBadOptions) {
  PositioningStage::Options o;
  o.capture_radius = -1.0;
  EXPECT_THROW(PositioningStage{o}, UserError);
  o = {};
  o.alignment_tolerance = 2.0;
  EXPECT_THROW(PositioningStage{o}, UserError);
}

TEST(ConstrainedStageTest, EvaluatesAnalyzerAndLawAndHandsBackWhenWithdrawn) {
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(3));
  const auto& analyzer = static_cast<const testing::FakeAnalyzer&>(*prepared.analyzer);
  const ConstrainedStage stage(*prepared.analyzer, *prepared.law);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  PartState s = At(0.0, 5e-3, -(analyzer.clearance() + 2e-6));
  stage.Evaluate(s, stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kConstrained);
  EXPECT_TRUE(out.contact.engaged);
  EXPECT_NEAR(out.contact.penetration, 2e-6, 1e-15);
  // k_p * penetration, pushing the part back up towards the axis.
  EXPECT_NEAR(out.wrench.force.z(), 1e5 * 2e-6, 1e-9);
  EXPECT_NEAR(out.wrench.force.x(), 0.0, 1e-9);
  EXPECT_LT(out.wrench.force.y(), 0.0);
  // The fake law's radial spring, found by the stage's own difference.
  EXPECT_NEAR(out.stiffness, 1e5, 1e-3);
  EXPECT_TRUE(std::isinf(out.gap));  // in contact: no free way
  stage.Evaluate(At(0.0, 5e-3, -0.5 * analyzer.clearance()), stage_run.get(), &out);
  EXPECT_EQ(out.stiffness, 0.0);
  // Free: half the clearance left, downwards along the offset.
  EXPECT_NEAR(out.gap, 0.5 * analyzer.clearance(), 1e-18);
  EXPECT_NEAR(out.gap_direction.y(), -1.0, 1e-15);
  EXPECT_NEAR(out.gap_direction.x(), 0.0, 1e-15);

  stage.Evaluate(At(0.0, -1e-6, 0.0), stage_run.get(), &out);
  EXPECT_EQ(out.next, StageId::kPositioning);
}

TEST(ConstrainedStageTest, SettlesThePartWhereTheContactCarriesItsLoad) {
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(3));
  const auto& analyzer = static_cast<const testing::FakeAnalyzer&>(*prepared.analyzer);
  const ConstrainedStage stage(*prepared.analyzer, *prepared.law);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  // The device holds the part on the axis; a 2 N load along -z settles it at clearance + W/k.
  PartState s = At(0.0, 5e-3, 0.0);
  s.settle_load = Eigen::Vector2d(0.0, -2.0);
  stage.Evaluate(s, stage_run.get(), &out);
  // Along the load, balanced to 1e-6 of it (2 uN, i.e. 2e-11 m on this 1e5 N/m spring).
  EXPECT_NEAR(out.pose.offset.y(), -(analyzer.clearance() + 2.0 / 1e5), 3e-11);
  EXPECT_NEAR(out.pose.offset.x(), 0.0, 1e-15);
  EXPECT_NEAR(out.wrench.force.z(), 2.0, 3e-6);  // balances the load
  EXPECT_EQ(out.stiffness, 0.0);                 // nothing for the device to integrate
  EXPECT_TRUE(std::isinf(out.gap));
  // A load along +x, starting from that equilibrium: the part slides round until the sideways
  // push is below 1 % of the load, and carries the load along x.
  s.settle_load = Eigen::Vector2d(3.0, 0.0);
  stage.Evaluate(s, stage_run.get(), &out);
  EXPECT_NEAR(out.wrench.force.x(), -3.0, 3e-6);
  EXPECT_LE(std::abs(out.wrench.force.z()), 0.03);
  EXPECT_GT(out.pose.offset.x(), analyzer.clearance());
  const double radial = std::hypot(out.wrench.force.x(), out.wrench.force.z());
  EXPECT_NEAR(out.pose.offset.norm(), analyzer.clearance() + radial / 1e5, 1e-12);
  // Not yet engaged: nothing carries the load, the device's own pose stands.
  s = At(0.0, 0.0, 0.0);
  s.settle_load = Eigen::Vector2d(0.0, -2.0);
  stage.Evaluate(s, stage_run.get(), &out);
  EXPECT_EQ(out.pose.offset, Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(out.wrench.force.z(), 0.0);
}

// A contact given in closed form for the settling tests, counting its evaluations; Contact fills
// what the fake law reads (penetration along offset_angle) beyond what is common.
class CountingAnalyzer : public ContactAnalyzer {
 public:
  int evaluations() const { return evaluations_; }

 protected:
  virtual void Contact(const MatingPose& pose, ContactState* out) const noexcept = 0;

 private:
  void DoPrepare(const PartSpec&, const SkinModelShape&, const PartSpec&, const SkinModelShape&,
                 const ModelSettings&) override {}
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept final {
    ++evaluations_;
    out->engaged = pose.depth > 0.0;
    out->engaged_length = std::max(0.0, pose.depth);
    out->offset_distance = pose.offset.norm();
    out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
    Contact(pose, out);
  }

  mutable int evaluations_ = 0;  // a test's count; the stage only reads the analyzer
};

// A robot's feed of 10 um per tick from 5 mm deep with a 2 N load along -z, settled on
// `analyzer` for `ticks` ticks: calls check(tick, output) after each and returns each tick's
// evaluations (checked against the stage's own count).
// With `then_at`, one tick more with the device at that depth (passed to check as tick `ticks`).
std::vector<int> SettleFeed(CountingAnalyzer* analyzer, int ticks,
                            const std::function<void(int, const StageOutput&)>& check,
                            std::optional<double> then_at = std::nullopt) {
  PreparedScene prepared = Prepare(testing::MakeFakeScene(3));
  analyzer->Prepare(PartSpec{}, *prepared.inner_sms, PartSpec{}, *prepared.outer_sms,
                    ModelSettings{});
  const ConstrainedStage stage(*analyzer, *prepared.law);
  const std::unique_ptr<StageState> stage_run = stage.MakeState();
  StageOutput out;
  PartState s = At(0.0, 5e-3, 0.0);
  s.settle_load = Eigen::Vector2d(0.0, -2.0);
  std::vector<int> per_tick;
  for (int tick = 0; tick < ticks + (then_at ? 1 : 0); ++tick) {
    s.position.y() = tick < ticks ? 5e-3 + 1e-5 * tick : *then_at;
    const int before = analyzer->evaluations();
    stage.Evaluate(s, stage_run.get(), &out);
    per_tick.push_back(analyzer->evaluations() - before);
    EXPECT_EQ(out.contact_evaluations, per_tick.back());  // the stage counts what it evaluates
    check(tick, out);
  }
  return per_tick;
}

// A bore narrowing with depth (a taper's clearance, 1 um per mm of depth from 20 um): the
// settled offset follows a straight path over depth.
class NarrowingAnalyzer final : public CountingAnalyzer {
 public:
  static double Clearance(double depth) { return 20e-6 - 1e-3 * depth; }

 protected:
  void Contact(const MatingPose& pose, ContactState* out) const noexcept override {
    out->assembly_extent = Clearance(pose.depth);
    out->penetration = std::max(0.0, out->offset_distance - out->assembly_extent);
  }
};

TEST(ConstrainedStageTest, SettlingFollowsTheBalancesPathOverDepth) {
  NarrowingAnalyzer analyzer;
  // The part rests on the narrowing wall, rising 10 nm per tick (far beyond the settle's
  // tolerance of 2e-11 m on this spring).
  const std::vector<int> per_tick = SettleFeed(&analyzer, 20, [](int, const StageOutput& out) {
    EXPECT_NEAR(out.pose.offset.y(), -(NarrowingAnalyzer::Clearance(out.pose.depth) + 2.0 / 1e5),
                3e-11);
  });
  // From the third tick on (two roots give the path's slope) the start lands on the balance:
  // one evaluation, where the last tick's root would need a second (a Newton step).
  for (std::size_t tick = 3; tick < per_tick.size(); ++tick) EXPECT_EQ(per_tick[tick], 1) << tick;
}

// An interference fit pressed deeper (the fake law's force is the stiffness times the reported
// penetration along the reported angle): a linear 2-D contact -K (offset - centre) whose
// stiffness grows 3 % and whose centre moves 10 nm sideways a tick, on a curved path (a taper's
// press, its parts' form).
class PressedFitAnalyzer final : public CountingAnalyzer {
 public:
  // Relative stiffness (times the law's) and centre of the contact at `depth`.
  static double Stiffening(double depth) { return 1e3 * (1.0 + 3e3 * (depth - 5e-3)); }
  static Eigen::Vector2d Centre(double depth) {
    const double d = depth - 5e-3;
    return {1e-3 * d + 100.0 * d * d, 0.0};
  }

 protected:
  void Contact(const MatingPose& pose, ContactState* out) const noexcept override {
    if (!out->engaged) return;
    const Eigen::Vector2d e = pose.offset - Centre(pose.depth);
    out->interference = true;
    out->offset_angle = std::atan2(e.y(), e.x());
    out->penetration = Stiffening(pose.depth) * e.norm();
  }
};

TEST(ConstrainedStageTest, SettlingAPressFitStepsOnItsLastStiffnessAndItsSecant) {
  PressedFitAnalyzer analyzer;
  const auto check = [](int tick, const StageOutput& out) {
    if (tick == 20) {
      // Pulled out: nothing carries the load, so no step on the last stiffness either; the
      // device's own pose stands.
      EXPECT_EQ(out.pose.offset, Eigen::Vector2d(0.0, 0.0));
      EXPECT_EQ(out.wrench.force.z(), 0.0);
      return;
    }
    // Balanced: along the load to 1e-3 of it, sideways to 1 % (ConstrainedStage::Settle).
    EXPECT_NEAR(out.wrench.force.z(), 2.0, 2e-3) << tick;
    EXPECT_LE(std::abs(out.wrench.force.x()), 0.02) << tick;
    // 1e8 N/m and more: the balance lies 20 nm below the centre.
    const Eigen::Vector2d from_centre =
        out.pose.offset - PressedFitAnalyzer::Centre(out.pose.depth);
    EXPECT_NEAR(from_centre.y(), -2.0 / (1e5 * PressedFitAnalyzer::Stiffening(out.pose.depth)),
                1e-11)
        << tick;
  };
  const std::vector<int> per_tick = SettleFeed(&analyzer, 20, check, -1e-6);
  // Once the path and the stiffness are known, a tick costs its start, the step on the last
  // tick's stiffness and the step on its secant correction (measured: 3; by differences, 4 to
  // 10; with a search along the load first, 4).
  for (std::size_t tick = 3; tick < 20; ++tick) EXPECT_LE(per_tick[tick], 3) << tick;
}

// A wall that steepens as the part goes in (the fake law's force is the stiffness times the
// reported penetration: here the square of the overlap over 1 nm, a texture's onset), in a bore
// whose narrowing slows, so that the start extrapolated along the path falls short of the wall.
class SteepeningWallAnalyzer final : public CountingAnalyzer {
 public:
  static double Clearance(double depth) {
    const double d = depth - 5e-3;
    return 20e-6 - 1e-3 * d + 100.0 * d * d;
  }

 protected:
  void Contact(const MatingPose& pose, ContactState* out) const noexcept override {
    out->assembly_extent = Clearance(pose.depth);
    const double overlap = std::max(0.0, out->offset_distance - out->assembly_extent);
    out->penetration = overlap * overlap / 1e-9;
  }
};

TEST(ConstrainedStageTest, SettlingOnASteepeningWallBracketsByTheSecant) {
  SteepeningWallAnalyzer analyzer;
  const std::vector<int> per_tick = SettleFeed(&analyzer, 40, [](int tick, const StageOutput& out) {
    // 2 N at an overlap of sqrt(2 / 1e5 * 1e-9) m = 141 nm, where the wall's slope is 2.8e7 N/m:
    // balanced to a picometre (2.8e-5 N), the searches' resolution, above 1e-6 of the load.
    EXPECT_NEAR(out.wrench.force.z(), 2.0, 2.9e-5) << tick;
    EXPECT_NEAR(-out.pose.offset.y() - SteepeningWallAnalyzer::Clearance(out.pose.depth),
                std::sqrt(2.0 / 1e5 * 1e-9), 1.01e-12)
        << tick;
  });
  // The start extrapolated along the path and the Newton step on the last root's slope fall
  // short of the wall; the secant through them, a tenth further, brackets the root tightly
  // (measured: 5.0 evaluations a tick; widening eightfold from the short step instead, 9.1).
  EXPECT_LE(std::accumulate(per_tick.begin() + 3, per_tick.end(), 0), 6 * 37);
}

}  // namespace
}  // namespace fitfeel
