#include "framework/iso965/fit.h"

#include <cmath>
#include <numbers>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/testing/units.h"

namespace fitfeel::iso965 {
namespace {

using test_support::kUm;
using ::testing::HasSubstr;

// M10x1.5 6H/6g: D2 9.026 .. 9.206 mm, d2 8.862 .. 8.994 mm (ISO 965-2), so the pitch-diameter
// clearance runs from 32 um to 344 um.
TEST(Iso965Fit, M10CoarseMediumFit) {
  const ThreadFit fit = LookupFit("M10x1.5", "6H/6g");
  EXPECT_NEAR(fit.min_clearance / kUm, 32, 1e-9);
  EXPECT_NEAR(fit.max_clearance / kUm, 344, 1e-9);
  const double tan30 = 1.0 / std::sqrt(3.0);
  EXPECT_NEAR(fit.min_axial_play / kUm, 32 * tan30, 1e-9);
  EXPECT_NEAR(fit.max_axial_play / kUm, 344 * tan30, 1e-9);
  EXPECT_NEAR(fit.max_axial_play / kUm, 198.6085, 1e-4);
  EXPECT_NEAR(fit.min_angular_backlash, 2 * std::numbers::pi * 32 * tan30 / 1500, 1e-12);
  EXPECT_NEAR(fit.max_angular_backlash * 180 / std::numbers::pi, 47.666, 1e-3);
  EXPECT_EQ(fit.nut.designation.text, "M10x1.5 6H");
  EXPECT_EQ(fit.bolt.designation.text, "M10x1.5 6g");
  // The coarse pitch is implied.
  EXPECT_EQ(LookupFit("M10", "6H/6g").max_clearance, fit.max_clearance);
}

// The play from the profile itself: the flank of the bolt in an axial plane is
// z = P/4 - tan(alpha/2) (r - r2); moving r2 in by c/2 moves it by tan(alpha/2) c/2, and both
// flanks of a tooth and of the nut's groove together give c tan(alpha/2).
TEST(Iso965Fit, AxialPlayFromTheFlankLines) {
  const ThreadFit fit = LookupFit("M10x1.25", "6H/6g");
  const double pitch = 1.25e-3;
  const double k = std::tan(fit.flank_angle / 2.0);
  const auto flank = [&](double r, double r2) { return pitch / 4.0 - k * (r - r2); };
  const double r = 4.8e-3;  // any radius on both flanks
  // The nut's groove has the profile of a bolt tooth on the nut's pitch radius.
  const double nut_groove = 2.0 * flank(r, fit.nut.pitch_diameter.max() / 2.0);
  const double bolt_tooth = 2.0 * flank(r, fit.bolt.pitch_diameter.min() / 2.0);
  EXPECT_NEAR(nut_groove - bolt_tooth, fit.max_axial_play, 1e-15);
}

TEST(Iso965Fit, Refusals) {
  const auto refused = [](const char* size, const char* code, const std::string& says) {
    try {
      LookupFit(size, code);
      ADD_FAILURE() << size << " " << code << " was accepted";
    } catch (const UserError& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(says)) << size << " " << code;
    }
  };
  refused("M10", "6H", "a thread fit is written NUT/bolt (e.g. 6H/6g), found '6H'");
  refused("M10", "6g/6H", "the first class of a thread fit must be an internal thread's");
  refused("M10", "6H/6G", "the second class of a thread fit must be an external thread's");
  refused("M10x1.4", "6H/6g", "1.4 mm is not an ISO 261 pitch of M10");
}

}  // namespace
}  // namespace fitfeel::iso965
