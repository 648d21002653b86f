#include "surfaces/cylindrical/cylindrical_discretizer.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical {
namespace {

using testing::Part;

TEST(CylindricalDiscretizer, AutoResolutionFollowsFormWavelengths) {
  const CylindricalDiscretizer d;
  // 1.25 mm axial pitch (10 mm / 8); K = floor(pi d / 10 mm) harmonics, 8 cells per lobe, >= 48.
  SurfaceGrid g = d.Discretize(Part("s", Role::kInner, 0.020, 0.020, 0, 0), {});
  EXPECT_EQ(g.rows, 16);
  EXPECT_EQ(g.columns, 48);
  g = d.Discretize(Part("s", Role::kInner, 0.020, 0.060, 0, 0), {});
  EXPECT_EQ(g.rows, 48);
  g = d.Discretize(Part("s", Role::kInner, 0.100, 0.003, 0, 0), {});
  EXPECT_EQ(g.rows, 3);          // fewest rows that can bend an axis
  EXPECT_EQ(g.columns, 8 * 31);  // pi * 100 / 10 = 31.4 lobes
  g = d.Discretize(Part("s", Role::kInner, 0.004, 0.010, 0, 0), {});
  EXPECT_EQ(g.rows, 8);
  EXPECT_EQ(g.columns, 48);
}

TEST(CylindricalDiscretizer, CellsTileTheNominalSurface) {
  const CylindricalDiscretizer d;
  for (const Role role : {Role::kInner, Role::kOuter}) {
    const PartSpec part = Part("p", role, 0.025, 0.037, 0, 0);
    const SurfaceGrid g = d.Discretize(part, {7, 30});
    ASSERT_EQ(g.rows, 7);
    ASSERT_EQ(g.columns, 30);
    EXPECT_NEAR(g.area.sum(), std::numbers::pi * 0.025 * 0.037, 1e-15);
    EXPECT_NEAR(g.area.sum(), part.geometry->nominal_area(), 1e-15);
    EXPECT_DOUBLE_EQ(g.area.minCoeff(), g.area.maxCoeff());
    for (int i = 0; i < g.rows; ++i) {
      EXPECT_NEAR(g.row_position(i), (i + 0.5) * 0.037 / 7, 1e-15);
      for (int j = 0; j < g.columns; ++j) {
        const int c = g.index(i, j);
        const double beta = 2.0 * std::numbers::pi * j / 30;
        EXPECT_NEAR(g.column_angle(j), beta, 1e-15);
        EXPECT_NEAR(g.normal.col(c).norm(), 1.0, 1e-15);
        EXPECT_NEAR(g.normal(1, c), 0.0, 0.0);
        EXPECT_NEAR(g.centre(0, c), 0.0125 * std::cos(beta), 1e-15);
        EXPECT_NEAR(g.centre(2, c), 0.0125 * std::sin(beta), 1e-15);
        EXPECT_NEAR(g.centre(1, c), g.row_position(i), 0.0);
      }
    }
  }
}

TEST(CylindricalDiscretizer, RefusesUnusableResolutions) {
  const CylindricalDiscretizer d;
  const PartSpec part = Part("p", Role::kInner, 0.02, 0.02, 0, 0);
  EXPECT_THROW(d.Discretize(part, {4, 31}), UserError);  // odd: no opposite cells
  EXPECT_THROW(d.Discretize(part, {4, 2}), UserError);
  EXPECT_THROW(d.Discretize(part, {-1, 8}), UserError);
  EXPECT_THROW(d.Discretize(part, {100000, 100000}), UserError);
  PartSpec none = part;
  none.geometry.reset();
  EXPECT_THROW(d.Discretize(none, {4, 8}), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
