// Table values of ISO 286 checked one by one: the oracles of docs/oracles.md, values
// printed in ISO 286-2 (and reproduced in every fits handbook) and the worked examples of ISO
// 286-1.

#include "framework/iso286/iso286.h"
#include "framework/testing/units.h"

#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace fitfeel::iso286 {
namespace {

using ::testing::HasSubstr;

// Deviations are tabulated in micrometres; compare in micrometres with a rounding allowance far
// below the table's 0.05 um resolution.
using test_support::kUm;
constexpr double kTol = 1e-9;

struct Expected {
  double nominal_mm;
  const char* code;
  double lower_um;
  double upper_um;
};

void ExpectLimits(const Expected& e) {
  SCOPED_TRACE(std::to_string(e.nominal_mm) + " mm " + e.code);
  const Limits l = Lookup(e.nominal_mm * 1e-3, e.code);
  EXPECT_NEAR(l.lower_deviation / kUm, e.lower_um, kTol);
  EXPECT_NEAR(l.upper_deviation / kUm, e.upper_um, kTol);
  EXPECT_NEAR(l.it / kUm, e.upper_um - e.lower_um, kTol);
}

// js/JS whose odd IT was rounded down: the class is 1 um narrower than its IT.
void ExpectRoundedSymmetric(double nominal_mm, const char* code, double half_um, double it_um) {
  SCOPED_TRACE(std::to_string(nominal_mm) + " mm " + code);
  const Limits l = Lookup(nominal_mm * 1e-3, code);
  EXPECT_NEAR(l.lower_deviation / kUm, -half_um, kTol);
  EXPECT_NEAR(l.upper_deviation / kUm, half_um, kTol);
  EXPECT_NEAR(l.it / kUm, it_um, kTol);
}

double ItUm(double nominal_mm, const std::string& grade) {
  return Lookup(nominal_mm * 1e-3, "h" + grade).it / kUm;
}

// docs/oracles.md: size step 18-30 mm.
TEST(Iso286Oracles, StandardTolerances18To30) {
  EXPECT_DOUBLE_EQ(ItUm(20, "5"), 9);
  EXPECT_DOUBLE_EQ(ItUm(20, "6"), 13);
  EXPECT_DOUBLE_EQ(ItUm(20, "7"), 21);
  EXPECT_DOUBLE_EQ(ItUm(20, "8"), 33);
  EXPECT_DOUBLE_EQ(ItUm(20, "9"), 52);
  EXPECT_DOUBLE_EQ(ItUm(20, "10"), 84);
  EXPECT_DOUBLE_EQ(ItUm(20, "11"), 130);
}

TEST(Iso286Oracles, TwentyMillimetreClasses) {
  ExpectLimits({20, "H7", 0, 21});
  ExpectLimits({20, "g6", -20, -7});
  ExpectLimits({20, "js6", -6.5, 6.5});
}

TEST(Iso286Oracles, ThirtyToFiftyStep) {
  ExpectLimits({40, "H7", 0, 25});
  ExpectLimits({40, "js6", -8, 8});
  // 50 mm is the top of the 30-50 step.
  ExpectLimits({50, "H7", 0, 25});
}

TEST(Iso286Values, CommonFits) {
  ExpectLimits({50, "k6", 2, 18});   // H7/k6 at 50 mm
  ExpectLimits({25, "p6", 22, 35});  // H7/p6 at 25 mm
  ExpectLimits({100, "f7", -71, -36});
  ExpectLimits({10, "N7", -19, -4});
  ExpectLimits({20, "h6", -13, 0});
  ExpectLimits({20, "h9", -52, 0});
  ExpectLimits({20, "m6", 8, 21});
  ExpectLimits({20, "n6", 15, 28});
  ExpectLimits({20, "r6", 28, 41});
  ExpectLimits({20, "s6", 35, 48});
  ExpectLimits({20, "u6", 41, 54});
  ExpectLimits({20, "c11", -240, -110});
  ExpectLimits({20, "d9", -117, -65});
  ExpectLimits({20, "e8", -73, -40});
  ExpectLimits({40, "f7", -50, -25});
  ExpectLimits({20, "G7", 7, 28});
  ExpectLimits({20, "F8", 20, 53});
  ExpectLimits({20, "A11", 300, 430});
  ExpectLimits({20, "J7", -9, 12});
  ExpectLimits({40, "K7", -18, 7});
  ExpectLimits({20, "K6", -11, 2});
  ExpectLimits({20, "K8", -23, 10});
  ExpectLimits({20, "M7", -21, 0});
  ExpectLimits({20, "N7", -28, -7});
  ExpectLimits({20, "P7", -35, -14});
  ExpectLimits({20, "S7", -48, -27});
  ExpectLimits({20, "U7", -54, -33});
  ExpectLimits({2, "P7", -16, -6});
  ExpectLimits({2, "j6", -2, 4});
  ExpectLimits({2, "J6", -4, 2});
  ExpectLimits({25, "t6", 41, 54});
}

// Parallel-key keyways (ISO 2491/DIN 6885 widths 6-10 mm): N9, P9, JS9.
TEST(Iso286Values, KeywayClasses) {
  ExpectLimits({8, "N9", -36, 0});
  ExpectLimits({8, "P9", -51, -15});
  ExpectLimits({8, "JS9", -18, 18});
  ExpectLimits({8, "D10", 40, 98});
  ExpectLimits({8, "h9", -36, 0});
}

// The worked examples of ISO 286-1 (footnote to Table 3): K7 in 18-30 mm has ES = -2 + 8 = +6 um;
// S6 in 18-30 mm has ES = -35 + 4 = -31 um.
TEST(Iso286Rules, DeltaExamplesOfTheStandard) {
  ExpectLimits({20, "K7", -15, 6});
  ExpectLimits({20, "S6", -44, -31});
}

// Above IT7 (P-ZC) and IT8 (K, M, N) the hole mirrors the shaft without Delta.
TEST(Iso286Rules, NoDeltaAboveTheLimitGrade) {
  ExpectLimits({20, "P8", -55, -22});
  ExpectLimits({20, "M9", -60, -8});
  ExpectLimits({20, "N9", -52, 0});
  ExpectLimits({2, "N9", -29, -4});
  ExpectLimits({2, "K9", -25, 0});
}

TEST(Iso286Rules, M6SpecialCase) {
  ExpectLimits({300, "M6", -41, -9});
  // Elsewhere M6 follows the rule: 18-30 mm, -8 + 4.
  ExpectLimits({20, "M6", -17, -4});
}

// js7..js11: an odd IT is rounded down to even before halving; js5, js6 keep the half micrometre.
TEST(Iso286Rules, JsRounding) {
  ExpectRoundedSymmetric(20, "js7", 10, 21);
  ExpectRoundedSymmetric(40, "js7", 12, 25);
  ExpectRoundedSymmetric(100, "js7", 17, 35);
  ExpectRoundedSymmetric(40, "JS8", 19, 39);
  ExpectRoundedSymmetric(40, "js9", 31, 62);  // even IT: no rounding
  ExpectLimits({20, "js5", -4.5, 4.5});
  ExpectLimits({40, "js11", -80, 80});
  ExpectLimits({20, "js13", -165, 165});
}

TEST(Iso286Sizes, BoundaryBelongsToLowerStep) {
  EXPECT_DOUBLE_EQ(ItUm(30, "7"), 21);
  EXPECT_DOUBLE_EQ(ItUm(30.001, "7"), 25);
  EXPECT_DOUBLE_EQ(ItUm(3, "7"), 10);
  EXPECT_DOUBLE_EQ(ItUm(3.0001, "7"), 12);
  EXPECT_DOUBLE_EQ(ItUm(500, "7"), 63);
  // Intermediate steps: 24 mm is in 18-24 (u = +41), 24.5 mm in 24-30 (u = +48).
  ExpectLimits({24, "u6", 41, 54});
  ExpectLimits({24.5, "u6", 48, 61});
  const Limits l = Lookup(0.03, "H7");
  EXPECT_DOUBLE_EQ(l.step_lower, 0.018);
  EXPECT_DOUBLE_EQ(l.step_upper, 0.030);
}

TEST(Iso286Sizes, FinestGradesAndSmallSizes) {
  EXPECT_DOUBLE_EQ(ItUm(0.5, "01"), 0.3);
  EXPECT_DOUBLE_EQ(ItUm(0.5, "0"), 0.5);
  EXPECT_DOUBLE_EQ(ItUm(450, "01"), 4);
  EXPECT_DOUBLE_EQ(ItUm(450, "18"), 9700);
  ExpectLimits({20, "js01", -0.3, 0.3});
  EXPECT_EQ(Lookup(0.02, "h01").code, "h01");
}

void ExpectCodeRefused(double nominal_mm, const std::string& code, const std::string& fragment) {
  SCOPED_TRACE(std::to_string(nominal_mm) + " mm " + code);
  try {
    Lookup(nominal_mm * 1e-3, code);
    ADD_FAILURE() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr(fragment));
  }
}

TEST(Iso286Errors, UnknownLetterOrGrade) {
  ExpectCodeRefused(20, "I7", "unknown ISO 286 fundamental deviation 'I'");
  ExpectCodeRefused(20, "Js6", "unknown ISO 286 fundamental deviation 'Js'");
  ExpectCodeRefused(20, "w6", "unknown ISO 286 fundamental deviation 'w'");
  ExpectCodeRefused(20, "7", "has no fundamental deviation letter");
  ExpectCodeRefused(20, "H", "has no grade");
  ExpectCodeRefused(20, "H19", "unknown ISO 286 standard tolerance grade '19'");
  ExpectCodeRefused(20, "H00", "unknown ISO 286 standard tolerance grade '00'");
  ExpectCodeRefused(20, "H07", "unknown ISO 286 standard tolerance grade '07'");
  ExpectCodeRefused(20, "H7x", "unknown ISO 286 standard tolerance grade '7x'");
  ExpectCodeRefused(20, "", "has no fundamental deviation letter");
}

TEST(Iso286Errors, SizeOutsideTables) {
  ExpectCodeRefused(0, "H7", "outside the ISO 286 tables");
  ExpectCodeRefused(-5, "H7", "outside the ISO 286 tables");
  ExpectCodeRefused(500.01, "H7", "outside the ISO 286 tables");
  ExpectCodeRefused(1e6, "H7", "outside the ISO 286 tables");
  EXPECT_THROW(Lookup(std::nan(""), "H7"), std::invalid_argument);
}

TEST(Iso286Errors, UndefinedCombinations) {
  ExpectCodeRefused(20, "t6", "does not define t6 at 20 mm");
  ExpectCodeRefused(10, "v6", "does not define v6");
  ExpectCodeRefused(15, "y6", "does not define y6");
  ExpectCodeRefused(20, "T7", "does not define T7");
  ExpectCodeRefused(1, "a11", "not used for sizes up to 1 mm");
  ExpectCodeRefused(0.8, "B11", "not used for sizes up to 1 mm");
  ExpectCodeRefused(20, "cd8", "up to 10 mm only");
  ExpectCodeRefused(12, "EF7", "up to 10 mm only");
  ExpectCodeRefused(20, "j9", "j is defined for IT5 to IT8 only");
  ExpectCodeRefused(20, "j8", "j8 is defined up to 3 mm only");
  ExpectCodeRefused(20, "J5", "J is defined for IT6 to IT8 only");
  ExpectCodeRefused(20, "J9", "J is defined for IT6 to IT8 only");
  ExpectCodeRefused(20, "K9", "K above IT8 is defined up to 3 mm only");
  ExpectCodeRefused(1, "N9", "N above IT8 is not used for sizes up to 1 mm");
  ExpectCodeRefused(1, "h14", "IT14 to IT18 are not used for sizes up to 1 mm");
  ExpectCodeRefused(20, "K2", "Delta");
  ExpectCodeRefused(20, "P1", "Delta");
}

TEST(Iso286Errors, AllowedNearRefusals) {
  ExpectLimits({1.5, "a11", -330, -270});
  ExpectLimits({10, "cd8", -78, -56});
  ExpectLimits({2, "j8", -6, 8});
  ExpectLimits({1.5, "N9", -29, -4});
  ExpectLimits({1.5, "h14", -250, 0});
  ExpectLimits({25, "T7", -54, -33});  // -41 + 8
}

}  // namespace
}  // namespace fitfeel::iso286
