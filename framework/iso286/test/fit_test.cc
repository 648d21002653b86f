#include "framework/iso286/fit.h"

#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/units.h"

namespace fitfeel::iso286 {
namespace {

using test_support::kUm;

void ExpectFit(double nominal_mm, const char* code, double min_um, double max_um,
               FitClass fit_class) {
  SCOPED_TRACE(std::to_string(nominal_mm) + " mm " + code);
  const Fit fit = LookupFit(nominal_mm * 1e-3, code);
  EXPECT_NEAR(fit.min_clearance / kUm, min_um, 1e-9);
  EXPECT_NEAR(fit.max_clearance / kUm, max_um, 1e-9);
  EXPECT_EQ(fit.fit_class, fit_class) << ToString(fit.fit_class);
}

TEST(Iso286Fit, PaperCase) {
  // H7/g6 at 20 mm: hole 0/+21, shaft -20/-7.
  ExpectFit(20, "H7/g6", 7, 41, FitClass::kClearance);
  // H7/js6 at 20 mm: shaft +-6.5.
  ExpectFit(20, "H7/js6", -6.5, 27.5, FitClass::kTransition);
}

TEST(Iso286Fit, PreferredFits) {
  ExpectFit(20, "H11/c11", 110, 370, FitClass::kClearance);
  ExpectFit(40, "H8/f7", 25, 89, FitClass::kClearance);
  ExpectFit(50, "H7/k6", -18, 23, FitClass::kTransition);
  ExpectFit(20, "H7/n6", -28, 6, FitClass::kTransition);
  ExpectFit(25, "H7/p6", -35, -1, FitClass::kInterference);
  ExpectFit(20, "H7/s6", -48, -14, FitClass::kInterference);
  ExpectFit(20, "H7/u6", -54, -20, FitClass::kInterference);
  ExpectFit(20, "P7/h6", -35, -1, FitClass::kInterference);
}

// Zero clearance counts as clearance (H/h), zero interference as interference (ISO 286-1
// definitions of the fits include the extreme case).
TEST(Iso286Fit, LimitCases) {
  ExpectFit(20, "H7/h6", 0, 34, FitClass::kClearance);
  Limits hole = Lookup(0.02, "H7");
  Limits shaft = Lookup(0.02, "h6");
  shaft.lower_deviation = hole.upper_deviation;
  shaft.upper_deviation = hole.upper_deviation + 13 * kUm;
  const Fit touching = MakeFit(hole, shaft);
  EXPECT_EQ(touching.max_clearance, 0.0);
  EXPECT_EQ(touching.fit_class, FitClass::kInterference);
}

TEST(Iso286Fit, ClassMatchesClearanceSigns) {
  for (const char* code : {"H7/g6", "H7/js6", "H7/k6", "H7/m6", "H7/n6", "H7/p6", "H7/r6", "H7/s6",
                           "H8/e8", "H9/d9", "G7/h6", "K7/h6", "N7/h6", "S7/h6"}) {
    for (double mm : {2.0, 8.0, 20.0, 45.0, 100.0, 300.0, 480.0}) {
      const Fit fit = LookupFit(mm * 1e-3, code);
      SCOPED_TRACE(std::to_string(mm) + " mm " + code);
      EXPECT_LT(fit.min_clearance, fit.max_clearance);
      EXPECT_NEAR(fit.max_clearance - fit.min_clearance,
                  fit.hole.upper_deviation - fit.hole.lower_deviation + fit.shaft.upper_deviation -
                      fit.shaft.lower_deviation,
                  1e-15);
      switch (fit.fit_class) {
        case FitClass::kClearance:
          EXPECT_GE(fit.min_clearance, 0.0);
          break;
        case FitClass::kInterference:
          EXPECT_LE(fit.max_clearance, 0.0);
          break;
        case FitClass::kTransition:
          EXPECT_LT(fit.min_clearance, 0.0);
          EXPECT_GT(fit.max_clearance, 0.0);
          break;
      }
    }
  }
}

TEST(Iso286Fit, MalformedFits) {
  EXPECT_THROW(LookupFit(0.02, "H7"), std::invalid_argument);
  EXPECT_THROW(LookupFit(0.02, "H7/g6/h5"), std::invalid_argument);
  EXPECT_THROW(LookupFit(0.02, "/g6"), std::invalid_argument);
  try {
    LookupFit(0.02, "g6/H7");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("must be a hole"));
  }
  try {
    LookupFit(0.02, "H7/G6");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("must be a shaft"));
  }
  EXPECT_THROW(LookupFit(0.02, "H7/t6"), std::invalid_argument);
  EXPECT_THROW(LookupFit(0.6, "H7/g6"), std::invalid_argument);
}

}  // namespace
}  // namespace fitfeel::iso286
