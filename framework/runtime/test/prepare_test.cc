#include "framework/runtime/prepare.h"

#include "framework/core/error.h"
#include "framework/runtime/test/fake_scene.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

TEST(PrepareTest, DrawsInnerThenOuterFromOneGeneratorSeededByTheScene) {
  const Scene scene = testing::MakeFakeScene(42);
  const PreparedScene prepared = Prepare(scene);

  // The same draws done by hand, in the documented order.
  Rng rng(42);
  testing::FakeDiscretizer discretizer;
  testing::FakeGenerator generator;
  const auto grid = discretizer.Discretize(scene.inner, scene.model.resolution);
  const auto inner = generator.Generate(scene.inner, grid, TextureMode::kExpected, rng);
  const auto outer = generator.Generate(scene.outer, grid, TextureMode::kExpected, rng);
  EXPECT_EQ(prepared.inner_sms->variation, inner.variation);
  EXPECT_EQ(prepared.outer_sms->variation, outer.variation);
  // The generator handed on continues after both parts' draws.
  Rng after = prepared.rng;
  EXPECT_EQ(after(), rng());

  EXPECT_TRUE(prepared.analyzer->prepared());
  ASSERT_NE(prepared.law, nullptr);
  EXPECT_GE(prepared.total_seconds, 0.0);
  EXPECT_GE(prepared.total_seconds, prepared.discretize_seconds + prepared.generate_seconds +
                                        prepared.analyze_seconds - 1e-9);
}

TEST(PrepareTest, AnotherSeedGivesOtherSkinModelShapes) {
  const PreparedScene a = Prepare(testing::MakeFakeScene(1));
  const PreparedScene b = Prepare(testing::MakeFakeScene(2));
  EXPECT_NE(a.inner_sms->variation, b.inner_sms->variation);
}

class MuteSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override { return {}; }
  std::vector<std::string> DoLawNames() const override { return {"none"}; }
  bool DoRendersForces() const override { return false; }
  std::string DoLimitation() const override { return "thread contact is not modelled"; }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override { return nullptr; }
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override { return nullptr; }
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override { return nullptr; }

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec&,
                                                  const ConfigNode&) const override {
    return nullptr;
  }
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view) const override { return nullptr; }
};

TEST(PrepareTest, RefusesASurfaceThatCannotRenderForcesWithItsReason) {
  Scene scene = testing::MakeFakeScene(1, 1.0, nullptr, std::make_shared<MuteSurface>());
  try {
    Prepare(scene);
    FAIL() << "expected UnsupportedError";
  } catch (const UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("thread contact is not modelled"), std::string::npos);
  }
}

TEST(PrepareTest, RefusesASceneWithoutSurface) {
  Scene scene = testing::MakeFakeScene(1);
  scene.surface = nullptr;
  EXPECT_THROW(Prepare(scene), UserError);
}

}  // namespace
}  // namespace fitfeel
