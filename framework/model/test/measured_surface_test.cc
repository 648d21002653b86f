// Resampling a measured part onto a cylinder's grid: exact where samples sit on the cells, within
// linear interpolation's error of a known field elsewhere, for all three kinds of measurement.
#include "framework/model/measured_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/testing/units.h"

namespace fitfeel {
namespace {

using test_support::kPi;
constexpr double kRadius = 0.01;

SurfaceGrid Cylinder(int rows, int columns, double length) {
  SurfaceGrid g;
  g.rows = rows;
  g.columns = columns;
  g.row_position.resize(rows);
  g.column_angle.resize(columns);
  for (int i = 0; i < rows; ++i) g.row_position(i) = (i + 0.5) * length / rows;
  for (int j = 0; j < columns; ++j) g.column_angle(j) = 2 * kPi * j / columns;
  g.centre.resize(3, g.size());
  g.normal.resize(3, g.size());
  g.area = Eigen::VectorXd::Constant(g.size(), 1e-6);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const double c = std::cos(g.column_angle(j)), s = std::sin(g.column_angle(j));
      g.centre.col(g.index(i, j)) << kRadius * c, g.row_position(i), kRadius * s;
      g.normal.col(g.index(i, j)) << c, 0.0, s;
    }
  }
  return g;
}

// A smooth deviation field: size, ovality, a taper (micrometres).
double Field(double y, double beta) {
  return 2e-6 + 3e-6 * std::cos(2 * beta + 0.3) + 1e-4 * y;
}

// Every cell of `sms` within `bound` of the field at its centre, heights clamped to [lo, hi].
void ExpectField(const SkinModelShape& sms, double bound, double lo = -1.0, double hi = 1.0) {
  const SurfaceGrid& g = sms.grid;
  for (int i = 0; i < g.rows; ++i) {
    for (int j = 0; j < g.columns; ++j) {
      const double y = std::clamp(g.row_position(i), lo, hi);
      EXPECT_NEAR(sms.variation(g.index(i, j)), Field(y, g.column_angle(j)), bound) << i << " " << j;
    }
  }
}

TEST(MeasuredSurface, CellsSampledExactlyReadBackBitForBit) {
  const SurfaceGrid g = Cylinder(5, 12, 0.02);
  MeasuredSurface m;
  std::mt19937_64 rng(4);
  std::normal_distribution<double> noise(0.0, 1e-6);
  Eigen::VectorXd v(g.size());
  for (int i = 0; i < g.rows; ++i) {
    for (int j = 0; j < g.columns; ++j) {
      v(g.index(i, j)) = noise(rng);
      m.height.push_back(g.row_position(i));
      m.angle.push_back(g.column_angle(j));
      m.value.push_back(v(g.index(i, j)));
    }
  }
  const SkinModelShape sms = MeasuredSkinModelShape(m, g, kRadius);
  for (int c = 0; c < g.size(); ++c) EXPECT_EQ(sms.variation(c), v(c)) << c;
  EXPECT_LT((sms.dimension_part + sms.form_part - sms.variation).cwiseAbs().maxCoeff(), 1e-20);
  EXPECT_EQ(sms.surface_part.cwiseAbs().maxCoeff(), 0.0);

  // The same samples as absolute radii.
  MeasuredSurface r = m;
  r.absolute = true;
  for (double& x : r.value) x += kRadius;
  const SkinModelShape back = MeasuredSkinModelShape(r, g, kRadius);
  EXPECT_LT((back.variation - v).cwiseAbs().maxCoeff(), 1e-17);  // one rounding of the radius
}

TEST(MeasuredSurface, RoundnessTracesInterpolateBetweenHeightsAndAngles) {
  const SurfaceGrid g = Cylinder(20, 48, 0.02);
  MeasuredSurface m;
  m.kind = MeasurementKind::kRoundness;
  // 5 traces, 90 points each, offset from the grid's angles.
  for (int k = 0; k < 5; ++k) {
    for (int a = 0; a < 90; ++a) {
      const double y = 0.0005 + k * 0.00475, beta = 2 * kPi * (a + 0.37) / 90;
      m.height.push_back(y);
      m.angle.push_back(beta);
      m.value.push_back(Field(y, beta));
    }
  }
  const SkinModelShape sms = MeasuredSkinModelShape(m, g, kRadius);
  // Linear interpolation of cos(2 beta) over 4 degrees: error <= (2 pi / 90)^2 / 8 * 4 * 3 um.
  ExpectField(sms, std::pow(2 * kPi / 90, 2) / 8 * 4 * 3e-6 + 1e-15, 0.0005, 0.0195);
}

TEST(MeasuredSurface, StraightnessTracesInterpolateBetweenAngles) {
  const SurfaceGrid g = Cylinder(20, 48, 0.02);
  MeasuredSurface m;
  m.kind = MeasurementKind::kStraightness;
  for (int k = 0; k < 72; ++k) {
    for (int s = 0; s <= 40; ++s) {
      const double beta = 2 * kPi * k / 72 + 0.01, y = s * 0.0005;
      m.height.push_back(y);
      m.angle.push_back(beta);
      m.value.push_back(Field(y, beta));
    }
  }
  const SkinModelShape sms = MeasuredSkinModelShape(m, g, kRadius);
  ExpectField(sms, std::pow(2 * kPi / 72, 2) / 8 * 4 * 3e-6 + 1e-15);
}

TEST(MeasuredSurface, PointCloudAveragesPerCellAndFillsGaps) {
  const SurfaceGrid g = Cylinder(10, 24, 0.02);
  MeasuredSurface m;
  m.kind = MeasurementKind::kPoints;
  m.absolute = true;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> y(0.0, 0.02), beta(0.0, 2 * kPi);
  // Dense scan, but nothing in rows 3 and 4 nor in one column's sector of row 7.
  for (int p = 0; p < 40000; ++p) {
    const double yy = y(rng), bb = beta(rng);
    if (yy > 0.006 && yy < 0.01) continue;
    if (yy > 0.014 && yy < 0.016 && bb > 1.0 - kPi / 24 && bb < 1.0 + kPi / 24) continue;
    m.height.push_back(yy);
    m.angle.push_back(bb);
    m.value.push_back(kRadius + Field(yy, bb));
  }
  const SkinModelShape sms = MeasuredSkinModelShape(m, g, kRadius);
  // A cell's mean of a field varying by at most 2 * 3 um * (pi / 24) + 1e-4 * 1 mm over half a
  // cell either way, plus the interpolated gaps over two rows: 1.2 um is generous, 3 um is not.
  ExpectField(sms, 1.2e-6);
}

TEST(MeasuredSurface, RefusesAGridThatIsNotACylinder) {
  SurfaceGrid g = Cylinder(3, 8, 0.01);
  g.centre(0, 0) *= 1.1;
  MeasuredSurface m;
  m.height = {0.0};
  m.angle = {0.0};
  m.value = {0.0};
  EXPECT_THROW(MeasuredSkinModelShape(m, g, kRadius), UnsupportedError);
}

TEST(MeasurementCsv, WritesOneSamplePerCellWithItsUnits) {
  const SurfaceGrid g = Cylinder(2, 4, 0.01);
  SkinModelShape sms;
  sms.grid = g;
  sms.variation = Eigen::VectorXd::Zero(8);
  sms.variation(7) = 1e-6;
  const std::string text = MeasurementCsv(sms, "a\nb");
  EXPECT_EQ(text.rfind("# a\n# b\nheight [m],angle [rad],deviation [m]\n", 0), 0u) << text;
  EXPECT_NE(text.find("\n0.0075,4.71238898038469,1e-06\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace fitfeel
