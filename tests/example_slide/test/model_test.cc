// Oracle tests of the example slide surface: the press-fit force by hand, the clearance interval,
// the engagement, the size draws and the refusals.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "tests/example_slide/example_slide_contact_analyzer.h"
#include "tests/example_slide/example_slide_geometry.h"
#include "tests/example_slide/example_slide_law.h"
#include "tests/example_slide/example_slide_shape.h"
#include "tests/example_slide/example_slide_surface.h"

namespace fitfeel::example_slide {
namespace {

// Steel block b = 10 mm, flank height 5 mm, 20 mm long, in a 30 mm slot between 10 mm rails.
PartSpec Block(double deviation) {
  PartSpec p;
  p.name = "block";
  p.role = Role::kInner;
  p.size = {10e-3, deviation, deviation, ""};
  p.material = {"steel", 210e9, 0.3};
  p.geometry = std::make_shared<SlideGeometry>(10e-3, 20e-3, 5e-3, 0.0);
  return p;
}

PartSpec Slot(double deviation) {
  PartSpec p = Block(deviation);
  p.name = "slot";
  p.role = Role::kOuter;
  p.geometry = std::make_shared<SlideGeometry>(10e-3, 30e-3, 5e-3, 10e-3);
  return p;
}

ModelSettings Settings() {
  ModelSettings s;
  s.law = "spring";
  s.friction = 0.15;
  s.contact_stiffness = 2e6;  // 2 N/um
  return s;
}

// Analyzer and law prepared on shapes drawn by the real discretizer and generator.
struct Model {
  SlideContactAnalyzer analyzer;
  SlideSpringLaw law;
  Model(const PartSpec& block, const PartSpec& slot, std::uint64_t seed = 1) {
    SlideDiscretizer discretizer;
    SlideVariationGenerator generator;
    Rng rng(seed);
    const SkinModelShape a =
        generator.Generate(block, discretizer.Discretize(block, {}), TextureMode::kExpected, rng);
    const SkinModelShape b =
        generator.Generate(slot, discretizer.Discretize(slot, {}), TextureMode::kExpected, rng);
    analyzer.Prepare(block, a, slot, b, Settings());
    law.Prepare(block, slot, Settings());
  }
  Wrench At(double depth, double x, double vy = 0.01) const {
    MatingPose pose;
    pose.depth = depth;
    pose.offset.x() = x;
    ContactState contact;
    analyzer.Evaluate(pose, &contact);
    MatingMotion motion;
    motion.velocity.y() = vy;
    Wrench w;
    law.Evaluate(contact, motion, &w);
    return w;
  }
};

TEST(SlideSurface, PressFitForceMatchesTheHandCalculation) {
  // The block 4 um wider than the slot: delta = 2 um per flank. c = 10 mm * 0.91 / 210 GPa =
  // 4.33333e-14 m/Pa for the block and each rail, P = 2 / (3 c) = 1.538462e13 Pa/m,
  // p = 30.769 MPa, F = 0.15 * 2 flanks * 30.769 MPa * 5 mm * 20 mm = 923.077 N.
  const Model m(Block(4e-6), Slot(0.0));
  EXPECT_NEAR(m.law.PressurePerInterference(), 1.538462e13, 1e7);
  EXPECT_NEAR(m.analyzer.clearance(), -2e-6, 1e-18);
  const double vy = 0.01;
  const double tanh = std::tanh(vy / kFrictionSmoothingVelocity);
  EXPECT_NEAR(m.At(20e-3, 0.0, vy).force.y(), -923.077 * tanh, 1e-3);
  // Half engaged, half the force; fully inside a longer slot, the full force; pulled out, reversed.
  EXPECT_NEAR(m.At(10e-3, 0.0, vy).force.y(), -461.538 * tanh, 1e-3);
  EXPECT_NEAR(m.At(25e-3, 0.0, vy).force.y(), -923.077 * tanh, 1e-3);
  EXPECT_NEAR(m.At(25e-3, 0.0, -vy).force.y(), 923.077 * tanh, 1e-3);
  EXPECT_EQ(m.At(25e-3, 0.0, vy).force.x(), 0.0);
}

TEST(SlideSurface, ClearanceLeavesTheBlockFreeUpToAFlank) {
  // 10 um clearance per flank: the block slides freely within +-10 um, then meets k_p.
  const Model m(Block(-10e-6), Slot(10e-6));
  EXPECT_NEAR(m.analyzer.clearance(), 10e-6, 1e-18);
  EXPECT_EQ(m.At(15e-3, 9e-6).force.norm(), 0.0);
  const Wrench right = m.At(15e-3, 15e-6);
  EXPECT_NEAR(right.force.x(), -10.0, 1e-9);  // 2 N/um * 5 um
  EXPECT_NEAR(right.force.y(), -0.15 * 10.0 * std::tanh(10.0), 1e-9);
  EXPECT_NEAR(m.At(15e-3, -15e-6).force.x(), 10.0, 1e-9);
  // Nothing faces z.
  MatingPose pose;
  pose.depth = 15e-3;
  pose.offset = Eigen::Vector2d(0.0, 1e-3);
  ContactState contact;
  m.analyzer.Evaluate(pose, &contact);
  EXPECT_EQ(contact.penetration, 0.0);
}

TEST(SlideSurface, EngagementFollowsTheDepth) {
  const Model m(Block(4e-6), Slot(0.0));
  ContactState contact;
  const auto at = [&](double depth) {
    MatingPose pose;
    pose.depth = depth;
    m.analyzer.Evaluate(pose, &contact);
    return contact;
  };
  EXPECT_FALSE(at(-1e-3).engaged);
  EXPECT_FALSE(at(0.0).engaged);
  EXPECT_NEAR(at(5e-3).engaged_length, 5e-3, 1e-15);
  EXPECT_NEAR(at(35e-3).engaged_length, 15e-3, 1e-15);  // the leading end is out again
  EXPECT_NEAR(at(35e-3).engaged_area, 2 * 5e-3 * 15e-3, 1e-15);
  EXPECT_FALSE(at(50e-3).engaged);
}

TEST(SlideSurface, GeneratorDrawsOneSizeInsideTheLimitsAndUsesThem) {
  PartSpec block = Block(0.0);
  block.size.lower_deviation = 15e-6;  // p6
  block.size.upper_deviation = 24e-6;
  SlideDiscretizer discretizer;
  SlideVariationGenerator generator;
  const SurfaceGrid grid = discretizer.Discretize(block, {4, 6});
  double least = 1.0, most = -1.0;
  for (int seed = 1; seed <= 500; ++seed) {
    Rng rng(seed);
    const SkinModelShape sms = generator.Generate(block, grid, TextureMode::kSampled, rng);
    ASSERT_EQ(sms.variation.maxCoeff(), sms.variation.minCoeff()) << "seed " << seed;
    const double deviation = 2.0 * sms.variation[0];
    ASSERT_GE(deviation, 15e-6);
    ASSERT_LE(deviation, 24e-6);
    least = std::min(least, deviation);
    most = std::max(most, deviation);
    for (const auto& check : EvaluateSlideCharacteristics(block, sms)) {
      EXPECT_NEAR(check.value, 10e-3 + deviation, 1e-15) << check.name;
    }
  }
  // 500 uniform draws leave less than 1 % of the range unused at either end (p = 0.99^500 = 0.7 %).
  EXPECT_LT(least, 15.09e-6);
  EXPECT_GT(most, 23.91e-6);
}

TEST(SlideSurface, GridCoversBothFlanks) {
  const PartSpec slot = Slot(0.0);
  const SurfaceGrid grid = SlideDiscretizer().Discretize(slot, {3, 4});
  EXPECT_NEAR(grid.area.sum(), 2 * 5e-3 * 30e-3, 1e-15);
  EXPECT_EQ(grid.normal(0, grid.index(1, 1)), 1.0);
  EXPECT_EQ(grid.normal(0, grid.index(1, 2)), -1.0);
  EXPECT_NEAR(grid.centre(0, grid.index(2, 3)), -5e-3, 1e-15);
  EXPECT_NEAR(grid.row_position[2], 25e-3, 1e-15);
  EXPECT_THROW(SlideDiscretizer().Discretize(slot, {3, 3}), UserError);
}

ConfigNode Node(const std::string& text) {
  return ConfigNode::Parse(text, "test.yaml", "parts.p.geometry");
}

TEST(SlideSurface, GeometryErrorsPointAtTheirKey) {
  const PartSpec slot = Slot(0.0);
  const PartSpec block = Block(0.0);
  auto key_of_error = [](const PartSpec& part, const std::string& text) -> std::string {
    try {
      ParseSlideGeometry(part, Node(text));
    } catch (const ScenarioError& e) {
      return e.key_path();
    }
    return "no error";
  };
  EXPECT_EQ(key_of_error(slot, "{length: 20 mm, height: 5 mm}"), "parts.p.geometry.rail_width");
  EXPECT_EQ(key_of_error(slot, "{length: -2 mm, height: 5 mm, rail_width: 8 mm}"),
            "parts.p.geometry.length");
  EXPECT_EQ(key_of_error(block, "{length: 20 mm, height: 5 mm, rail_width: 8 mm}"),
            "parts.p.geometry.rail_width");
  EXPECT_EQ(key_of_error(block, "{length: 20 mm, height: 5 mm}"), "no error");
  PartSpec rough = block;
  rough.texture.ra = 0.8e-6;
  EXPECT_EQ(key_of_error(rough, "{length: 20 mm, height: 5 mm}"), "parts.p.texture");
}

TEST(SlideSurface, AnalyzerRefusesAShapeWithForm) {
  const PartSpec block = Block(0.0), slot = Slot(0.0);
  SlideDiscretizer discretizer;
  SkinModelShape a, b;
  a.grid = discretizer.Discretize(block, {});
  b.grid = discretizer.Discretize(slot, {});
  a.variation = Eigen::VectorXd::Zero(a.grid.size());
  b.variation = Eigen::VectorXd::Zero(b.grid.size());
  a.variation[1] = 1e-6;
  SlideContactAnalyzer analyzer;
  EXPECT_THROW(analyzer.Prepare(block, a, slot, b, Settings()), UserError);
  a.variation[1] = 0.0;
  EXPECT_NO_THROW(analyzer.Prepare(block, a, slot, b, Settings()));
  SlideSpringLaw law;
  PartSpec soft = slot;
  soft.material.youngs_modulus = 0.0;
  EXPECT_THROW(law.Prepare(block, soft, Settings()), UserError);
}

}  // namespace
}  // namespace fitfeel::example_slide
