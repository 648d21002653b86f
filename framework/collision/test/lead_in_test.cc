#include "framework/collision/lead_in.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/testing/units.h"

namespace fitfeel {
namespace {

constexpr double kMm = 1e-3;
using test_support::kInf;
using test_support::kUm;

// A 20 mm shaft with a C0.5 end in a bore with a C1 entrance, `play` of radial clearance (< 0:
// interference), both chamfers at 45 degrees.
LeadIn ChamferedPair(double play) {
  const double shaft = 10 * kMm, bore = shaft + play;
  RadiusProfile moving, fixed;
  moving.points = {{0.0, shaft - 0.5 * kMm}, {0.5 * kMm, shaft}};
  fixed.points = {{0.0, bore + 1 * kMm}, {1 * kMm, bore}};
  return LeadIn(moving, fixed, -1 * kMm, 0.5 * kMm);
}

TEST(LeadInTest, TwoFortyFiveDegreeChamfersLeaveALinearFunnel) {
  const double c = 12 * kUm;
  const LeadIn lead_in = ChamferedPair(c);
  // Worked out by hand: every section of the shaft meets the bore's section at the same y with
  // the same margin while both are on their chamfers, c + 0.5 mm - y, down to the clearance
  // once the shaft's chamfer has passed the bore's edge (y = 0.5 mm).
  EXPECT_EQ(lead_in.MaxOffset(-1.001 * kMm), kInf);
  EXPECT_EQ(lead_in.MaxOffset(-1 * kMm), kInf);  // on the face's plane: on the face
  for (double y : {-0.999, -0.7, -0.2, 0.0, 0.3, 0.5}) {
    EXPECT_NEAR(lead_in.MaxOffset(y * kMm), c + 0.5 * kMm - y * kMm, 1e-12) << y;
  }
  for (double y : {0.6, 5.0, 40.0}) EXPECT_NEAR(lead_in.MaxOffset(y * kMm), c, 1e-12) << y;
  EXPECT_NEAR(lead_in.play(), c, 1e-15);
  EXPECT_NEAR(lead_in.capture_depth(), 0.5 * kMm, 1e-15);
}

TEST(LeadInTest, AnInterferenceFitWedgesOnTheAxisBeforeItsChamferEnds) {
  const LeadIn lead_in = ChamferedPair(-10 * kUm);
  EXPECT_NEAR(lead_in.play(), -10 * kUm, 1e-15);
  // c + 0.5 mm - y = 0 at y = 0.49 mm: the constrained stage (the press) takes over there.
  EXPECT_NEAR(lead_in.capture_depth(), 0.49 * kMm, 1e-12);
  EXPECT_NEAR(lead_in.boundary().back().x(), 0.49 * kMm, 1e-12);
  EXPECT_EQ(lead_in.boundary().back().y(), 0.0);
  // On the axis and past the wedge, the part stops at it.
  const Eigen::Vector2d part =
      lead_in.Project({2 * kMm, 0.0}, {-2 * kMm, 0.0});
  EXPECT_NEAR(part.x(), 0.49 * kMm, 1e-12);
  EXPECT_NEAR(part.y(), 0.0, 1e-12);
}

TEST(LeadInTest, SharpEdgesHandOverAtTheEntrance) {
  RadiusProfile moving, fixed;
  moving.points = {{0.0, 10 * kMm}};
  fixed.points = {{0.0, 10 * kMm + 5 * kUm}};
  const LeadIn lead_in(moving, fixed, 0.0, 0.0);
  EXPECT_EQ(lead_in.capture_depth(), 0.0);
  EXPECT_NEAR(lead_in.MaxOffset(1 * kMm), 5 * kUm, 1e-15);
  EXPECT_EQ(lead_in.MaxOffset(-1 * kUm), kInf);
}

TEST(LeadInTest, AFreeTargetIsWhereThePartGoes) {
  const LeadIn lead_in = ChamferedPair(12 * kUm);
  const Eigen::Vector2d target(-3 * kMm, 2 * kMm);
  EXPECT_EQ(lead_in.Project(target, {-4 * kMm, 2 * kMm}), target);
  const Eigen::Vector2d inside(0.2 * kMm, 0.1 * kMm);  // in the funnel, clear of its walls
  EXPECT_EQ(lead_in.Project(inside, {-4 * kMm, 0.0}), inside);
}

TEST(LeadInTest, APartPushedStraightInSlidesDownTheChamfer) {
  const double c = 12 * kUm;
  const LeadIn lead_in = ChamferedPair(c);
  // From 1 mm off the axis, pushed to y = 0: it meets the slope r + y = c + 0.5 mm and slides
  // down it to the foot of the perpendicular from the target.
  const Eigen::Vector2d part = lead_in.Project({0.0, 1 * kMm}, {-2 * kMm, 1 * kMm});
  EXPECT_NEAR(part.x() + part.y(), c + 0.5 * kMm, 1e-12);
  const double excess = 1 * kMm - (c + 0.5 * kMm);
  EXPECT_NEAR(part.x(), -excess / 2, 1e-12);
  EXPECT_NEAR(part.y(), 1 * kMm - excess / 2, 1e-12);
  // Pushed on, from there, the part keeps sliding in and towards the axis.
  Eigen::Vector2d at = part;
  for (int i = 1; i <= 2000; ++i) at = lead_in.Project({i * 1 * kUm, 1 * kMm}, at);
  EXPECT_TRUE(lead_in.Free(at));
  EXPECT_LE(at.y(), lead_in.MaxOffset(at.x()) + 1e-12);
}

TEST(LeadInTest, APartPressedOnTheFaceDoesNotTunnelIntoTheBore) {
  const LeadIn lead_in = ChamferedPair(12 * kUm);
  // 3 mm off the axis the shaft's end lands on the face (y = -1 mm), however hard it is pushed:
  // the nearest boundary point to a target 6 mm beyond the face is the bore's chamfer, but the
  // part cannot get there through the face.
  Eigen::Vector2d at(-2 * kMm, 3 * kMm);
  at = lead_in.Project({-0.9 * kMm, 3 * kMm}, at);
  EXPECT_NEAR(at.x(), -1 * kMm, 1e-15);
  EXPECT_NEAR(at.y(), 3 * kMm, 1e-15);
  at = lead_in.Project({5 * kMm, 3 * kMm}, at);
  EXPECT_NEAR(at.x(), -1 * kMm, 1e-15);
  EXPECT_NEAR(at.y(), 3 * kMm, 1e-15);
  // Moved towards the axis while pressed, it goes round the face's edge into the chamfer.
  at = lead_in.Project({-0.5 * kMm, 1.3 * kMm}, at);
  EXPECT_NEAR(at.x() + at.y(), 12 * kUm + 0.5 * kMm, 1e-12);
}

TEST(LeadInTest, RefusesProfilesThatAreNotParts) {
  RadiusProfile good, shrinking, empty;
  good.points = {{0.0, 9.5 * kMm}, {0.5 * kMm, 10 * kMm}};
  shrinking.points = {{0.0, 10 * kMm}, {0.5 * kMm, 9 * kMm}};
  EXPECT_THROW(LeadIn(shrinking, good, 0.0, 0.0), UserError);  // a shaft narrowing behind its tip
  EXPECT_THROW(LeadIn(good, good, 0.0, 0.0), UserError);       // a bore widening behind its face
  EXPECT_THROW(LeadIn(empty, shrinking, 0.0, 0.0), UserError);
  EXPECT_THROW(LeadIn(good, shrinking, 1 * kMm, 0.0), UserError);   // a face inside the bore
  EXPECT_THROW(LeadIn(good, shrinking, 0.0, -1 * kMm), UserError);  // mating before the entrance
}

}  // namespace
}  // namespace fitfeel
