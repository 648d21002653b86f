#include "surfaces/cylindrical/cylindrical_geometry.h"

#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_generator.h"
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

TEST(CylindricalVariationGenerator, ReadsItsModelOptions) {
  CylindricalVariationGenerator g;
  g.Configure(Node("{size_draw: per_cell, size_limit: radial}", "model.options"));
  EXPECT_EQ(g.options().size_draw, SizeDraw::kPerCell);
  EXPECT_EQ(g.options().size_limit, SizeLimit::kRadial);
  EXPECT_THROW(g.Configure(Node("{size_draw: per_row}", "model.options")), ScenarioError);
  EXPECT_THROW(g.Configure(Node("{sizes: per_cell}", "model.options")), ScenarioError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
