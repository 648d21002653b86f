// Parsing a planar part's geometry node and checking a pair: precise scenario errors.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/planar/planar_geometry.h"
#include "surfaces/planar/planar_surface.h"
#include "surfaces/planar/test/test_support.h"

namespace fitfeel::planar {
namespace {

using testing::MakePart;

ConfigNode Node(const std::string& yaml, const std::string& path = "parts.key.geometry") {
  return ConfigNode::Parse(yaml, "key.yaml", path);
}

TEST(PlanarGeometryTest, ParsesAKeyAndASquare) {
  const PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 1.0, 1.0);
  const auto g = ParsePlanarGeometry(key, Node("{length: 40 mm, height: 2.6 mm}"));
  EXPECT_EQ(g->faces(), 2);
  EXPECT_DOUBLE_EQ(g->width(), 8e-3);
  EXPECT_DOUBLE_EQ(g->nominal_area(), 2 * 40e-3 * 2.6e-3);
  const PartSpec square = MakePart("shaft", Role::kInner, 20e-3, -20e-6, -7e-6, 1.0, 1.0);
  const auto s = ParsePlanarGeometry(square, Node("{length: 30 mm, height: 18 mm, faces: 4}"));
  EXPECT_EQ(s->faces(), 4);
  EXPECT_DOUBLE_EQ(s->nominal_area(), 4 * 30e-3 * 18e-3);
}

TEST(PlanarGeometryTest, RefusesBadNodesAtTheirKey) {
  const PartSpec square = MakePart("shaft", Role::kInner, 20e-3, -20e-6, -7e-6, 1.0, 1.0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{length: 30, height: 18 mm}", "parts.key.geometry.length"},  // no unit
      {"{length: 30 mm}", "parts.key.geometry.height"},              // missing
      {"{length: 30 mm, height: 18 mm, faces: 3}", "parts.key.geometry.faces"},
      {"{length: 30 mm, height: 18 mm, faces: 6}", "parts.key.geometry.faces"},
      {"{length: 30 mm, height: 21 mm, faces: 4}", "parts.key.geometry.height"},  // > side
      {"{length: 30 mm, height: 18 mm, width: 20 mm}", "parts.key.geometry.width"},
      {"{length: -3 mm, height: 18 mm}", "parts.key.geometry.length"},
  };
  for (const auto& [yaml, key_path] : cases) {
    try {
      ParsePlanarGeometry(square, Node(yaml));
      ADD_FAILURE() << "accepted " << yaml;
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.key_path(), key_path) << yaml << ": " << e.what();
      EXPECT_EQ(e.where().file, "key.yaml");
      EXPECT_GT(e.where().line, 0);
    }
  }
}

TEST(PlanarGeometryTest, PairMustShareWidthFacesAndHeight) {
  const PlanarSurface surface;
  const ConfigNode pair = Node("{}", "parts");
  const PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 2.6e-3);
  EXPECT_NO_THROW(surface.CheckPair(
      key, MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 45e-3, 2.6e-3), pair));
  EXPECT_THROW(surface.CheckPair(
                   key, MakePart("slot", Role::kOuter, 10e-3, -18e-6, 18e-6, 45e-3, 2.6e-3), pair),
               ScenarioError);
  EXPECT_THROW(surface.CheckPair(
                   key, MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 45e-3, 3.3e-3), pair),
               ScenarioError);
  EXPECT_THROW(
      surface.CheckPair(key, MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 45e-3, 2.6e-3, 4),
                        pair),
      ScenarioError);
}

}  // namespace
}  // namespace fitfeel::planar
