#include "framework/core/quantity.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using ::testing::HasSubstr;

// The message of the std::invalid_argument ParseQuantity throws, or "" when it does not throw.
std::string ParseError(std::string_view text, Dimension dimension) {
  try {
    ParseQuantity(text, dimension);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ParseQuantityTest, ConvertsEveryLengthUnitExactly) {
  // Exact: the prefix is applied in decimal, so the result is the double nearest to the decimal
  // value, the same as writing the SI value in the file.
  EXPECT_EQ(ParseQuantity("20 mm", Dimension::kLength), 20e-3);
  EXPECT_EQ(ParseQuantity("8 um", Dimension::kLength), 8e-6);
  EXPECT_EQ(ParseQuantity("-8 um", Dimension::kLength), -8e-6);
  EXPECT_EQ(ParseQuantity("0.4 um", Dimension::kLength), 0.4e-6);
  EXPECT_EQ(ParseQuantity("3 nm", Dimension::kLength), 3e-9);
  EXPECT_EQ(ParseQuantity("2.5 cm", Dimension::kLength), 2.5e-2);
  EXPECT_EQ(ParseQuantity("1.25 m", Dimension::kLength), 1.25);
  EXPECT_EQ(ParseQuantity("1.5e1 mm", Dimension::kLength), 15e-3);
  EXPECT_EQ(ParseQuantity("20mm", Dimension::kLength), 20e-3);  // the space is optional
  EXPECT_EQ(ParseQuantity("  20 mm  ", Dimension::kLength), 20e-3);
  EXPECT_EQ(ParseQuantity(".5 mm", Dimension::kLength), 0.5e-3);
  EXPECT_EQ(ParseQuantity("+7 um", Dimension::kLength), 7e-6);
  EXPECT_EQ(ParseQuantity("8 \u00b5m", Dimension::kLength), 8e-6);  // micro sign accepted
  // 0.1 mm is exactly the double of 1e-4, not 0.1 * 1e-3 rounded twice.
  EXPECT_EQ(ParseQuantity("0.1 mm", Dimension::kLength), 1e-4);
}

TEST(ParseQuantityTest, ConvertsOtherDimensions) {
  EXPECT_EQ(ParseQuantity("210 GPa", Dimension::kPressure), 210e9);
  EXPECT_EQ(ParseQuantity("3 MPa", Dimension::kPressure), 3e6);
  EXPECT_EQ(ParseQuantity("4 kPa", Dimension::kPressure), 4e3);
  EXPECT_EQ(ParseQuantity("2 N", Dimension::kForce), 2.0);
  EXPECT_EQ(ParseQuantity("5 mN", Dimension::kForce), 5e-3);
  EXPECT_EQ(ParseQuantity("1.5 kN", Dimension::kForce), 1500.0);
  EXPECT_EQ(ParseQuantity("10 mm/s", Dimension::kVelocity), 10e-3);
  EXPECT_EQ(ParseQuantity("0.2 m/s", Dimension::kVelocity), 0.2);
  EXPECT_EQ(ParseQuantity("2 N/um", Dimension::kStiffness), 2e6);
  EXPECT_EQ(ParseQuantity("2 kN/mm", Dimension::kStiffness), 2e6);
  EXPECT_EQ(ParseQuantity("3 N/mm", Dimension::kStiffness), 3e3);
  EXPECT_EQ(ParseQuantity("400 N/m", Dimension::kStiffness), 400.0);
  EXPECT_EQ(ParseQuantity("1000 Hz", Dimension::kFrequency), 1000.0);
  EXPECT_EQ(ParseQuantity("2 kHz", Dimension::kFrequency), 2000.0);
  EXPECT_EQ(ParseQuantity("5 s", Dimension::kTime), 5.0);
  EXPECT_EQ(ParseQuantity("3 ms", Dimension::kTime), 3e-3);
  EXPECT_EQ(ParseQuantity("250 us", Dimension::kTime), 250e-6);
  EXPECT_EQ(ParseQuantity("2 N*s/m", Dimension::kDamping), 2.0);
  EXPECT_EQ(ParseQuantity("2 Ns/m", Dimension::kDamping), 2.0);
  EXPECT_EQ(ParseQuantity("150 g", Dimension::kMass), 0.15);
  EXPECT_EQ(ParseQuantity("1.2 kg", Dimension::kMass), 1.2);
  EXPECT_EQ(ParseQuantity("1 rad", Dimension::kAngle), 1.0);
  EXPECT_EQ(ParseQuantity("5 mrad", Dimension::kAngle), 5e-3);
  EXPECT_DOUBLE_EQ(ParseQuantity("180 deg", Dimension::kAngle), std::numbers::pi);
  EXPECT_DOUBLE_EQ(ParseQuantity("90 deg/s", Dimension::kAngularVelocity), std::numbers::pi / 2);
  EXPECT_EQ(ParseQuantity("2 rad/s", Dimension::kAngularVelocity), 2.0);
  EXPECT_EQ(ParseQuantity("3 N*m", Dimension::kTorque), 3.0);
  EXPECT_EQ(ParseQuantity("3 Nm", Dimension::kTorque), 3.0);
  EXPECT_EQ(ParseQuantity("40 N*mm", Dimension::kTorque), 0.04);
  EXPECT_EQ(ParseQuantity("7 N*m/rad", Dimension::kAngularStiffness), 7.0);
  EXPECT_EQ(ParseQuantity("0.5 J", Dimension::kEnergy), 0.5);
  EXPECT_EQ(ParseQuantity("0.15", Dimension::kDimensionless), 0.15);
  EXPECT_EQ(ParseQuantity("-0.2", Dimension::kDimensionless), -0.2);
}

TEST(ParseQuantityTest, RefusesMissingUnitNamingAcceptedUnits) {
  const std::string message = ParseError("20", Dimension::kLength);
  EXPECT_THAT(message, HasSubstr("expected a length (nm, um, mm, cm, m)"));
  EXPECT_THAT(message, HasSubstr("found '20' (no unit)"));
}

TEST(ParseQuantityTest, RefusesUnknownUnit) {
  const std::string message = ParseError("20 mmm", Dimension::kLength);
  EXPECT_THAT(message, HasSubstr("expected a length (nm, um, mm, cm, m)"));
  EXPECT_THAT(message, HasSubstr("unknown unit 'mmm'"));
  EXPECT_THAT(ParseError("3 furlongs", Dimension::kLength), HasSubstr("unknown unit 'furlongs'"));
  // Units are case-sensitive: MM is not mm, and Mpa is not MPa.
  EXPECT_THAT(ParseError("20 MM", Dimension::kLength), HasSubstr("unknown unit 'MM'"));
  EXPECT_THAT(ParseError("3 Mpa", Dimension::kPressure), HasSubstr("unknown unit 'Mpa'"));
}

TEST(ParseQuantityTest, RefusesUnitOfAnotherDimensionSayingWhichOne) {
  const std::string message = ParseError("20 kg", Dimension::kLength);
  EXPECT_THAT(message, HasSubstr("expected a length (nm, um, mm, cm, m)"));
  EXPECT_THAT(message, HasSubstr("found '20 kg' (kg is a unit of mass)"));
  EXPECT_THAT(
      ParseError("210 GPa", Dimension::kForce),
      HasSubstr("expected a force (mN, N, kN), found '210 GPa' (GPa is a unit of pressure)"));
  EXPECT_THAT(ParseError("2 N", Dimension::kStiffness), HasSubstr("N is a unit of force"));
  EXPECT_THAT(ParseError("0.15 mm", Dimension::kDimensionless),
              HasSubstr("mm is a unit of length; a dimensionless number has no unit"));
}

TEST(ParseQuantityTest, RefusesNonFiniteNumbers) {
  for (const char* text : {"inf mm", "-inf mm", ".inf mm", "nan mm", "NaN", "Infinity m"}) {
    EXPECT_THAT(ParseError(text, Dimension::kLength), HasSubstr("not a finite number")) << text;
  }
  EXPECT_THAT(ParseError("1e400 m", Dimension::kLength), HasSubstr("not a finite number"));
  EXPECT_THAT(ParseError("1e99999999999999999999 m", Dimension::kLength),
              HasSubstr("not a finite number"));
  EXPECT_THAT(ParseError("nan", Dimension::kDimensionless), HasSubstr("not a finite number"));
}

TEST(ParseQuantityTest, RefusesTrailingGarbageAndNonNumbers) {
  EXPECT_THAT(ParseError("20 mm x", Dimension::kLength),
              HasSubstr("found '20 mm x' (unexpected 'x' after the unit)"));
  EXPECT_THAT(ParseError("20 mm 30 mm", Dimension::kLength), HasSubstr("after the unit"));
  EXPECT_THAT(ParseError("0.15 abc", Dimension::kDimensionless),
              HasSubstr("unexpected 'abc' after the number"));
  EXPECT_THAT(ParseError("mm 20", Dimension::kLength), HasSubstr("found 'mm 20' (not a number)"));
  EXPECT_THAT(ParseError("twenty mm", Dimension::kLength), HasSubstr("(not a number)"));
  EXPECT_THAT(ParseError("", Dimension::kLength), HasSubstr("found an empty value"));
  EXPECT_THAT(ParseError("   ", Dimension::kLength), HasSubstr("found an empty value"));
  EXPECT_THAT(ParseError("1.2.3 mm", Dimension::kLength), HasSubstr("unknown unit '.3'"));
  EXPECT_THAT(ParseError("20,5 mm", Dimension::kLength), HasSubstr("unknown unit ',5'"));
}

TEST(DescribeDimensionTest, NamesTheDimensionAndItsUnits) {
  EXPECT_EQ(DescribeDimension(Dimension::kLength), "a length (nm, um, mm, cm, m)");
  EXPECT_EQ(DescribeDimension(Dimension::kPressure), "a pressure (Pa, kPa, MPa, GPa)");
  EXPECT_EQ(DescribeDimension(Dimension::kStiffness), "a stiffness (N/m, N/mm, N/um, kN/mm)");
  EXPECT_EQ(DescribeDimension(Dimension::kAngle), "an angle (rad, mrad, deg)");
  EXPECT_EQ(DescribeDimension(Dimension::kDimensionless),
            "a dimensionless number (no unit, e.g. 0.15)");
  EXPECT_EQ(DescribeDimension(Dimension::kFrequency), "a frequency (Hz, kHz)");
}

TEST(FormatQuantityTest, PicksAUnitSuitedToTheMagnitude) {
  EXPECT_EQ(FormatQuantity(2.0e-5, Dimension::kLength), "20 um");
  EXPECT_EQ(FormatQuantity(-8e-6, Dimension::kLength), "-8 um");
  EXPECT_EQ(FormatQuantity(0.02, Dimension::kLength), "20 mm");
  EXPECT_EQ(FormatQuantity(1.5, Dimension::kLength), "1.5 m");
  EXPECT_EQ(FormatQuantity(3e-10, Dimension::kLength), "0.0003 um");
  EXPECT_EQ(FormatQuantity(4e-7, Dimension::kLength), "0.4 um");
  EXPECT_EQ(FormatQuantity(0.0, Dimension::kLength), "0 m");
  EXPECT_EQ(FormatQuantity(210e9, Dimension::kPressure), "210 GPa");
  EXPECT_EQ(FormatQuantity(2e6, Dimension::kStiffness), "2 N/um");
  EXPECT_EQ(FormatQuantity(1000.0, Dimension::kFrequency), "1 kHz");
  EXPECT_EQ(FormatQuantity(100.0, Dimension::kFrequency), "100 Hz");
  EXPECT_EQ(FormatQuantity(3600.0, Dimension::kTime), "3600 s");
  EXPECT_EQ(FormatQuantity(0.01, Dimension::kVelocity), "10 mm/s");
  EXPECT_EQ(FormatQuantity(0.15, Dimension::kDimensionless), "0.15");
  EXPECT_EQ(FormatQuantity(std::numbers::pi, Dimension::kAngle), "180 deg");
}

TEST(FormatQuantityTest, ParsesBackToTheSameValue) {
  const Dimension dimensions[] = {Dimension::kLength, Dimension::kForce,     Dimension::kPressure,
                                  Dimension::kTime,   Dimension::kStiffness, Dimension::kMass};
  for (Dimension dimension : dimensions) {
    for (double value : {1.234567e-9, 7e-6, 0.0123, 1.0, 42.5, 9.87e4, 2.1e11}) {
      const std::string text = FormatQuantity(value, dimension);
      EXPECT_NEAR(ParseQuantity(text, dimension), value, 1e-9 * value) << text;
    }
  }
}

}  // namespace
}  // namespace fitfeel
