#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/conical_geometry.h"
#include "surfaces/conical/conical_surface.h"
#include "surfaces/conical/test/test_parts.h"

namespace fitfeel::conical {
namespace {

ConfigNode Node(const std::string& text) {
  return ConfigNode::Parse(text, "test.yaml", "parts.p.geometry");
}

TEST(ConicalGeometry, FrustumAreaAndDiameters) {
  const auto pin = test::Pin();
  const auto& g = GeometryOf(pin);
  EXPECT_DOUBLE_EQ(g.large_diameter(), 8e-3 + 40e-3 / 50.0);  // 8.8 mm
  EXPECT_DOUBLE_EQ(g.DiameterAt(0.0), 8e-3);
  const double alpha = std::atan(0.01);
  EXPECT_NEAR(g.nominal_area(), M_PI * 8.4e-3 * 40e-3 / std::cos(alpha), 1e-15);
  const auto hole = test::Hole();
  EXPECT_DOUBLE_EQ(GeometryOf(hole).DiameterAt(0.0), 8e-3 + 20e-3 / 50.0);  // entrance: large end
  EXPECT_DOUBLE_EQ(GeometryOf(hole).DiameterAt(20e-3), 8e-3);
}

TEST(ConicalGeometry, CellsSumToTheFrustumAndNormalsAreUnit) {
  for (const PartSpec& part : {test::Pin(), test::Hole()}) {
    for (Resolution r : {Resolution{}, Resolution{7, 10}, Resolution{50, 36}}) {
      const SurfaceGrid grid = ConicalDiscretizer().Discretize(part, r);
      EXPECT_NEAR(grid.area.sum(), part.geometry->nominal_area(),
                  1e-12 * part.geometry->nominal_area());
      for (int k = 0; k < grid.size(); ++k) EXPECT_NEAR(grid.normal.col(k).norm(), 1.0, 1e-15);
    }
  }
  const SurfaceGrid automatic = ConicalDiscretizer().Discretize(test::Pin(), Resolution{});
  EXPECT_EQ(automatic.rows, 20);  // one row per 2 mm of the 40 mm pin
  EXPECT_EQ(automatic.columns, 72);
}

TEST(ConicalGeometry, RefusesOddOrTooFewColumns) {
  EXPECT_THROW(ConicalDiscretizer().Discretize(test::Pin(), Resolution{10, 9}), UserError);
  EXPECT_THROW(ConicalDiscretizer().Discretize(test::Pin(), Resolution{10, 6}), UserError);
  EXPECT_THROW(ConicalDiscretizer().Discretize(test::Pin(), Resolution{2, 12}), UserError);
}

TEST(ConicalGeometry, ParsesTaperAsRatioOrNumber) {
  PartSpec pin = test::Pin();
  auto g = ParseConicalGeometry(pin, Node("{length: 40 mm, taper: '1:50'}"));
  EXPECT_DOUBLE_EQ(g->taper(), 0.02);
  EXPECT_DOUBLE_EQ(g->length(), 0.04);
  g = ParseConicalGeometry(pin, Node("{length: 40 mm, taper: 0.02}"));
  EXPECT_DOUBLE_EQ(g->taper(), 0.02);
  EXPECT_NEAR(g->half_angle(), std::atan(0.01), 1e-15);
}

TEST(ConicalGeometry, RefusesBadInputAtTheKey) {
  const PartSpec pin = test::Pin();
  const PartSpec hole = test::Hole();
  const auto expect_error = [](const PartSpec& p, const std::string& text, const std::string& key) {
    try {
      ParseConicalGeometry(p, Node(text));
      ADD_FAILURE() << "accepted " << text;
    } catch (const ScenarioError& e) {
      EXPECT_NE(e.key_path().find(key), std::string::npos) << e.what();
    }
  };
  expect_error(pin, "{length: 40 mm, taper: '1:x'}", "taper");
  expect_error(pin, "{length: 40 mm, taper: '1:5000'}", "taper");
  expect_error(pin, "{length: 40 mm}", "taper");
  expect_error(pin, "{length: 40, taper: '1:50'}", "length");
  expect_error(pin, "{length: 40 mm, taper: '1:50', outer_diameter: 20 mm}", "outer_diameter");
  expect_error(hole, "{length: 20 mm, taper: '1:50'}", "outer_diameter");
  // The hub must have a wall at the bore's large end (8.4 mm here).
  expect_error(hole, "{length: 20 mm, taper: '1:50', outer_diameter: 8.3 mm}", "outer_diameter");
}

}  // namespace
}  // namespace fitfeel::conical

namespace fitfeel::conical {
namespace {

TEST(ConicalSurface, CheckPairRefusesAnotherTaperOrSize) {
  const ConfigNode parts = ConfigNode::Parse("{pin: {size: 8 mm h10, geometry: {length: 40 mm, taper: "
                                    "'1:50'}}, hole: {size: 10 mm H10, geometry: {length: 20 mm, "
                                    "taper: '1:48', outer_diameter: 24 mm}}}",
                         "test.yaml", "parts");
  const ConicalSurface surface;
  const PartSpec pin = test::Pin();
  EXPECT_NO_THROW(surface.CheckPair(pin, test::Hole(), parts));
  PartSpec steeper = test::Hole();
  steeper.geometry = std::make_shared<ConicalGeometry>(Role::kOuter, 8e-3, 20e-3, 1.0 / 48, 24e-3);
  try {
    surface.CheckPair(pin, steeper, parts);
    ADD_FAILURE() << "accepted a 1:48 hole for a 1:50 pin";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "parts.hole.geometry.taper") << e.what();
    EXPECT_NE(e.expected().find("1:50"), std::string::npos) << e.what();
  }
  PartSpec bigger = test::Hole();
  bigger.size.nominal = 10e-3;
  bigger.geometry = std::make_shared<ConicalGeometry>(Role::kOuter, 10e-3, 20e-3, 0.02, 24e-3);
  try {
    surface.CheckPair(pin, bigger, parts);
    ADD_FAILURE() << "accepted a 10 mm hole for an 8 mm pin";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "parts.hole.size") << e.what();
  }
}

}  // namespace
}  // namespace fitfeel::conical
