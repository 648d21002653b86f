// ISO fastener dimensions and ISO 898-1 property classes: spot values against the standards'
// tables, and refusals that name what is held.
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/fastener_tables.h"

namespace fitfeel::thread {
namespace {

TEST(FastenerTablesTest, M10SpotValues) {
  const MetricFastener& m10 = MetricFastenerOf(10e-3);
  EXPECT_DOUBLE_EQ(m10.pitch, 1.5e-3);                    // ISO 261 coarse
  EXPECT_DOUBLE_EQ(m10.width_across_flats, 16e-3);        // ISO 4014 (DIN 931 had 17)
  EXPECT_DOUBLE_EQ(m10.head_height, 6.4e-3);              // ISO 4014 k nominal
  EXPECT_DOUBLE_EQ(m10.head_bearing_diameter, 14.63e-3);  // ISO 4014 d_w min, grade A
  EXPECT_EQ(m10.head_product_grade, 'A');
  EXPECT_DOUBLE_EQ(m10.nut_height, 8.4e-3);                               // ISO 4032 m max
  EXPECT_DOUBLE_EQ(m10.nut_bearing_diameter, 14.6e-3);                    // ISO 4032 d_w min
  EXPECT_DOUBLE_EQ(m10.clearance_hole(ClearanceSeries::kFine), 10.5e-3);  // ISO 273
  EXPECT_DOUBLE_EQ(m10.clearance_hole(ClearanceSeries::kMedium), 11e-3);
  EXPECT_DOUBLE_EQ(m10.clearance_hole(ClearanceSeries::kCoarse), 12e-3);
}

TEST(FastenerTablesTest, SmallestAndLargestSizes) {
  const MetricFastener& m3 = MetricFastenerOf(3e-3);
  EXPECT_DOUBLE_EQ(m3.width_across_flats, 5.5e-3);
  EXPECT_DOUBLE_EQ(m3.nut_height, 2.4e-3);
  EXPECT_DOUBLE_EQ(m3.clearance_medium, 3.4e-3);
  const MetricFastener& m36 = MetricFastenerOf(36e-3);
  EXPECT_DOUBLE_EQ(m36.pitch, 4e-3);
  EXPECT_DOUBLE_EQ(m36.width_across_flats, 55e-3);
  EXPECT_DOUBLE_EQ(m36.head_height, 22.5e-3);
  EXPECT_EQ(m36.head_product_grade, 'B');  // ISO 4014 grade A stops at M24
  EXPECT_DOUBLE_EQ(m36.nut_height, 31e-3);
  EXPECT_DOUBLE_EQ(m36.clearance_coarse, 42e-3);
}

TEST(FastenerTablesTest, EverySizeIsConsistent) {
  double previous = 0.0;
  for (const MetricFastener& f : MetricFasteners()) {
    const double d = f.nominal_diameter;
    EXPECT_GT(d, previous);
    previous = d;
    // A bearing face wider than the hole and narrower than the hexagon; a hole wider than the bolt.
    EXPECT_LT(f.clearance_coarse, f.head_bearing_diameter) << d;
    EXPECT_LT(f.head_bearing_diameter, f.width_across_flats) << d;
    EXPECT_LT(f.nut_bearing_diameter, f.width_across_flats) << d;
    EXPECT_LT(d, f.clearance_fine) << d;
    EXPECT_LT(f.clearance_fine, f.clearance_medium) << d;
    EXPECT_LT(f.clearance_medium, f.clearance_coarse) << d;
    // Style 1 nuts are 0.8 d to 0.95 d high (M3, M4: exactly 0.8 d); coarse pitches d/9 (M36) to
    // d/5.7 (M4).
    EXPECT_GE(f.nut_height, 0.8 * d * (1 - 1e-12)) << d;
    EXPECT_LT(f.nut_height, 0.95 * d) << d;
    EXPECT_GE(f.pitch, d / 9.0 * (1 - 1e-12)) << d;
    EXPECT_LE(f.pitch, d / 5.7) << d;
    EXPECT_EQ(&MetricFastenerOf(d), &f);
  }
  EXPECT_EQ(MetricFasteners().size(), 12u);
}

TEST(FastenerTablesTest, UnknownSizeIsRefusedNamingTheHeldOnes) {
  try {
    MetricFastenerOf(14e-3);
    FAIL() << "M14 is not held";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("14 mm"), std::string::npos) << what;
    EXPECT_NE(what.find("M3, M4, M5, M6, M8, M10, M12, M16, M20, M24, M30, M36"), std::string::npos)
        << what;
  }
  EXPECT_THROW(MetricFastenerOf(-10e-3), UserError);
  EXPECT_THROW(MetricFastenerOf(std::nan("")), UserError);
}

}  // namespace
}  // namespace fitfeel::thread
