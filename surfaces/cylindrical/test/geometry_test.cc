#include "surfaces/cylindrical/cylindrical_geometry.h"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_generator.h"
#include "surfaces/cylindrical/cylindrical_options.h"
#include "surfaces/cylindrical/elastic_options.h"
#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical {
namespace {

ConfigNode Node(const std::string& yaml, const std::string& path = "parts.p.geometry") {
  return ConfigNode::Parse(yaml, "scene.yaml", path);
}

PartSpec Spec(Role role, double d) {
  PartSpec p;
  p.name = "p";
  p.role = role;
  p.size.nominal = d;
  return p;
}

TEST(CylindricalGeometry, ParsesShaftAndHub) {
  auto shaft = ParseCylindricalGeometry(Spec(Role::kInner, 0.02), Node("{length: 60 mm}"));
  EXPECT_DOUBLE_EQ(shaft->diameter(), 0.02);
  EXPECT_DOUBLE_EQ(shaft->length(), 0.06);
  EXPECT_DOUBLE_EQ(shaft->bore_diameter(), 0.0);
  EXPECT_DOUBLE_EQ(shaft->nominal_area(), std::numbers::pi * 0.02 * 0.06);
  EXPECT_EQ(shaft->Describe(), "shaft d=20 mm l=60 mm");
  auto hollow = ParseCylindricalGeometry(Spec(Role::kInner, 0.02),
                                         Node("{length: 60 mm, bore_diameter: 12 mm}"));
  EXPECT_DOUBLE_EQ(hollow->bore_diameter(), 0.012);
  auto hub = ParseCylindricalGeometry(Spec(Role::kOuter, 0.02),
                                      Node("{length: 20 mm, outer_diameter: 30 mm}"));
  EXPECT_DOUBLE_EQ(hub->outer_diameter(), 0.03);
  EXPECT_EQ(hub->Describe(), "bore d=20 mm l=20 mm hub outer d=30 mm");
  // Lead-in chamfers: a length is ISO 13715's 45 degree "C" edge; or length and angle.
  auto c =
      ParseCylindricalGeometry(Spec(Role::kInner, 0.02), Node("{length: 60 mm, chamfer: 0.5 mm}"));
  EXPECT_DOUBLE_EQ(c->chamfer().length, 0.5e-3);
  EXPECT_NEAR(c->chamfer().width(), 0.5e-3, 1e-15);
  EXPECT_EQ(c->Describe(), "shaft d=20 mm l=60 mm chamfer 0.5 mm x 45 deg");
  auto steep = ParseCylindricalGeometry(
      Spec(Role::kOuter, 0.02),
      Node("{length: 20 mm, outer_diameter: 30 mm, chamfer: {length: 2 mm, angle: 15 deg}}"));
  EXPECT_NEAR(steep->chamfer().width(), 2e-3 * std::tan(std::numbers::pi / 12), 1e-15);
  EXPECT_DOUBLE_EQ(shaft->chamfer().length, 0.0);  // none given: a sharp edge
}

// Each bad geometry is refused at its key with what was expected.
TEST(CylindricalGeometry, RefusesBadGeometryAtTheKey) {
  struct Bad {
    Role role;
    const char* yaml;
    const char* key;
  };
  const Bad cases[] = {
      {Role::kInner, "{length: 0 mm}", "parts.p.geometry.length"},
      {Role::kInner, "{length: -3 mm}", "parts.p.geometry.length"},
      {Role::kInner, "{length: 20 N}", "parts.p.geometry.length"},
      {Role::kInner, "{}", "parts.p.geometry"},
      {Role::kInner, "{length: 20 mm, outer_diameter: 30 mm}", "parts.p.geometry"},
      {Role::kInner, "{length: 20 mm, bore_diameter: 20 mm}", "parts.p.geometry.bore_diameter"},
      {Role::kOuter, "{length: 20 mm}", "parts.p.geometry"},
      {Role::kOuter, "{length: 20 mm, outer_diameter: 20 mm}", "parts.p.geometry.outer_diameter"},
      {Role::kOuter, "{length: 20 mm, outer_diameter: 30 mm, bore_diameter: 5 mm}",
       "parts.p.geometry"},
      {Role::kInner, "{length: 20 mm, chamfer: 20 mm}", "parts.p.geometry.chamfer"},
      {Role::kInner, "{length: 60 mm, chamfer: 11 mm}", "parts.p.geometry.chamfer"},
      {Role::kOuter, "{length: 20 mm, outer_diameter: 30 mm, chamfer: 6 mm}",
       "parts.p.geometry.chamfer"},
      {Role::kOuter,
       "{length: 20 mm, outer_diameter: 30 mm, chamfer: {length: 1 mm, angle: 85 deg}}",
       "parts.p.geometry.chamfer.angle"},
      {Role::kInner, "{length: 20 mm, chamfer: {angle: 30 deg}}", "parts.p.geometry.chamfer"},
      {Role::kInner, "{length: 20 mm, chamfer: -1 mm}", "parts.p.geometry.chamfer"},
  };
  for (const Bad& bad : cases) {
    try {
      ParseCylindricalGeometry(Spec(bad.role, 0.02), Node(bad.yaml));
      ADD_FAILURE() << bad.yaml << " was accepted";
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.key_path().substr(0, std::string(bad.key).size()), bad.key) << bad.yaml;
      EXPECT_EQ(e.where().file, "scene.yaml");
    }
  }
}

TEST(CylindricalGeometry, PairNeedsOneNominalDiameter) {
  const ConfigNode pair = Node("{}", "parts");
  EXPECT_NO_THROW(CheckCylindricalPair(Spec(Role::kInner, 0.02), Spec(Role::kOuter, 0.02), pair));
  EXPECT_THROW(CheckCylindricalPair(Spec(Role::kInner, 0.02), Spec(Role::kOuter, 0.021), pair),
               ScenarioError);
}

TEST(CylindricalOptions, ParsesTheGeneratorsAndTheElasticLawsKeysOnce) {
  const auto parsed =
      ParseCylindricalOptions(Node("{size_draw: per_cell, size_limit: radial}", "model.options"));
  EXPECT_EQ(parsed->size_draw, SizeDraw::kPerCell);
  EXPECT_EQ(parsed->size_limit, SizeLimit::kRadial);
  CylindricalVariationGenerator g;
  g.Configure(*parsed);
  EXPECT_EQ(g.options().size_draw, SizeDraw::kPerCell);
  EXPECT_EQ(g.options().size_limit, SizeLimit::kRadial);
  EXPECT_THROW(ParseCylindricalOptions(Node("{size_draw: per_row}", "model.options")),
               ScenarioError);
  EXPECT_THROW(ParseCylindricalOptions(Node("{sizes: per_cell}", "model.options")),
               ScenarioError);
  // The elastic law's keys: axial_orders is an order from 0 to 12.
  for (int orders : {0, 12}) {
    const std::string yaml = "{axial_orders: " + std::to_string(orders) + "}";
    EXPECT_EQ(ParseCylindricalOptions(Node(yaml, "model.options"))->elastic.axial_orders, orders);
  }
  for (const char* bad : {"{axial_orders: 13}", "{axial_orders: -1}", "{axial_orders: two}"}) {
    EXPECT_THROW(ParseCylindricalOptions(Node(bad, "model.options")), ScenarioError) << bad;
  }
  EXPECT_EQ(ParseCylindricalOptions(Node("{}", "model.options"))->elastic.axial_orders,
            ElasticOptions::kDefaultAxialOrders);
  // Settings without options take the defaults; another surface's options are refused.
  EXPECT_EQ(CylindricalOptionsOf(ModelSettings{}).size_draw, SizeDraw::kPerPart);
  ModelSettings foreign;
  foreign.options = std::make_shared<const SurfaceOptions>();
  EXPECT_THROW(CylindricalOptionsOf(foreign), UserError);
  EXPECT_THROW(g.Configure(*foreign.options), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
