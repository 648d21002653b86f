// ISO 898-1 property classes: strengths by class and diameter, and refusals.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/property_class.h"

namespace fitfeel::thread {
namespace {

TEST(BoltPropertyClassTest, Iso898Values) {
  const BoltPropertyClass& c88 = BoltPropertyClass::Parse("8.8");
  EXPECT_EQ(c88.name(), "8.8");
  EXPECT_DOUBLE_EQ(c88.nominal_tensile_strength(), 800e6);
  EXPECT_DOUBLE_EQ(c88.min_yield_strength(10e-3), 640e6);
  EXPECT_DOUBLE_EQ(c88.min_yield_strength(16e-3), 640e6);  // d <= 16 mm inclusive
  EXPECT_DOUBLE_EQ(c88.min_yield_strength(20e-3), 660e6);
  EXPECT_DOUBLE_EQ(c88.min_tensile_strength(16e-3), 800e6);
  EXPECT_DOUBLE_EQ(c88.min_tensile_strength(20e-3), 830e6);
  const BoltPropertyClass& c109 = BoltPropertyClass::Parse("10.9");
  EXPECT_DOUBLE_EQ(c109.min_yield_strength(10e-3), 940e6);
  EXPECT_DOUBLE_EQ(c109.min_tensile_strength(36e-3), 1040e6);
  const BoltPropertyClass& c129 = BoltPropertyClass::Parse("12.9");
  EXPECT_DOUBLE_EQ(c129.min_yield_strength(10e-3), 1100e6);
  EXPECT_DOUBLE_EQ(c129.min_tensile_strength(10e-3), 1220e6);
  EXPECT_DOUBLE_EQ(BoltPropertyClass::Parse("4.6").min_yield_strength(10e-3), 240e6);
  EXPECT_DOUBLE_EQ(BoltPropertyClass::Parse("5.6").min_yield_strength(10e-3), 300e6);
}

TEST(BoltPropertyClassTest, TheClassNameEncodesTheStrengths) {
  // "a.b": R_m nominal = 100 a MPa, yield / R_m nominal = b / 10 (ISO 898-1 clause 4).
  for (const BoltPropertyClass& c : BoltPropertyClass::All()) {
    const std::string name(c.name());
    const double a = std::stod(name.substr(0, name.find('.')));
    const double b = std::stod(name.substr(name.find('.') + 1));
    EXPECT_DOUBLE_EQ(c.nominal_tensile_strength(), a * 100e6) << name;
    EXPECT_GE(c.min_yield_strength(10e-3), 0.99 * b / 10.0 * a * 100e6) << name;
    EXPECT_LT(c.min_yield_strength(10e-3), c.min_tensile_strength(10e-3)) << name;
  }
}

TEST(BoltPropertyClassTest, RefusesUnknownClassesListingTheValidOnes) {
  try {
    BoltPropertyClass::Parse("9.8");
    FAIL() << "9.8 is not held";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'9.8'"), std::string::npos) << what;
    EXPECT_NE(what.find("4.6, 5.6, 8.8, 10.9, 12.9"), std::string::npos) << what;
  }
  EXPECT_THROW(BoltPropertyClass::Parse(""), UserError);
  EXPECT_THROW(BoltPropertyClass::Parse("8.8 "), UserError);
  const BoltPropertyClass& c88 = BoltPropertyClass::Parse("8.8");
  EXPECT_THROW(c88.min_yield_strength(0.0), UserError);
  EXPECT_THROW(c88.min_tensile_strength(std::nan("")), UserError);
}

}  // namespace
}  // namespace fitfeel::thread
