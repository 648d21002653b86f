#include "surfaces/cylindrical/cylindrical_generator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/cylindrical/sms_conformance.h"
#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical {
namespace {

using testing::PaperHole;
using testing::PaperShaft;
using testing::Part;

SkinModelShape Make(const PartSpec& part, std::uint64_t seed, TextureMode texture,
                    GeneratorOptions options = {}) {
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, {});
  Rng rng(seed);
  return CylindricalVariationGenerator(options).Generate(part, grid, texture, rng);
}

TEST(CylindricalVariationGenerator, SameSeedSameShapeOtherSeedOtherShape) {
  const PartSpec part = PaperShaft();
  const SkinModelShape a = Make(part, 42, TextureMode::kSampled);
  const SkinModelShape b = Make(part, 42, TextureMode::kSampled);
  const SkinModelShape c = Make(part, 43, TextureMode::kSampled);
  ASSERT_EQ(a.variation.size(), b.variation.size());
  EXPECT_TRUE((a.variation.array() == b.variation.array()).all());  // bit for bit
  EXPECT_TRUE((a.form_part.array() == b.form_part.array()).all());
  EXPECT_EQ(a.regenerations, b.regenerations);
  EXPECT_FALSE((a.variation.array() == c.variation.array()).all());
}

TEST(CylindricalVariationGenerator, ZeroTolerancesGiveZeroVariation) {
  PartSpec part = Part("p", Role::kInner, 0.02, 0.03, 0.0, 0.0);
  part.form.tolerance[FormCharacteristic::kRoundness] = 0.0;
  part.form.tolerance[FormCharacteristic::kCylindricity] = 0.0;
  for (const TextureMode mode : {TextureMode::kExpected, TextureMode::kSampled}) {
    for (const SizeDraw draw : {SizeDraw::kPerPart, SizeDraw::kPerCell}) {
      const SkinModelShape s = Make(part, 5, mode, {draw, SizeLimit::kTwoPoint, 10});
      EXPECT_EQ(s.variation.cwiseAbs().maxCoeff(), 0.0);
    }
  }
}

TEST(CylindricalVariationGenerator, PartsAddUpAndSizeIsOnePerPart) {
  const PartSpec part = PaperHole();
  const SkinModelShape s = Make(part, 9, TextureMode::kExpected);
  EXPECT_LE((s.variation - s.dimension_part - s.form_part - s.surface_part).cwiseAbs().maxCoeff(),
            1e-21);
  EXPECT_EQ(s.surface_part.cwiseAbs().maxCoeff(), 0.0);  // texture left to the analyzer
  EXPECT_EQ(s.dimension_part.minCoeff(), s.dimension_part.maxCoeff());
  EXPECT_GE(2 * s.dimension_part(0), part.size.lower_deviation);
  EXPECT_LE(2 * s.dimension_part(0), part.size.upper_deviation);
  EXPECT_GT(s.form_part.cwiseAbs().maxCoeff(), 0.0);
}

TEST(CylindricalVariationGenerator, SampledTextureIsTheTruncatedGaussianOfEq6) {
  // Loose size so nothing is scaled back; no form. Heights within +-(A + Rz)/2 = +-2.4 um with
  // sigma = 0.8 um truncated at 3 sigma: standard deviation 0.9866 sigma.
  PartSpec part = Part("p", Role::kInner, 0.05, 0.2, -100e-6, 100e-6);
  part.texture = {3.2e-6, 0.4e-6, 1.6e-6};
  const SkinModelShape s = Make(part, 3, TextureMode::kSampled);
  ASSERT_GT(s.surface_part.size(), 10000);
  EXPECT_LE(s.surface_part.cwiseAbs().maxCoeff(), 2.4e-6);
  const double mean = s.surface_part.mean();
  const double sd = std::sqrt((s.surface_part.array() - mean).square().mean());
  EXPECT_NEAR(mean, 0.0, 0.03e-6);
  EXPECT_NEAR(sd, 0.9866 * 0.8e-6, 0.02e-6);
  EXPECT_EQ(s.scaled_back_cells, 0);
}

TEST(CylindricalVariationGenerator, PerCellSizeIsWhiteNoiseWithinTheLimits) {
  const PartSpec part = PaperShaft();
  const SkinModelShape s =
      Make(part, 11, TextureMode::kExpected, {SizeDraw::kPerCell, SizeLimit::kTwoPoint, 10});
  EXPECT_GT(s.dimension_part.maxCoeff() - s.dimension_part.minCoeff(), 4e-6);
  EXPECT_GE(s.dimension_part.minCoeff(), -4e-6);
  EXPECT_LE(s.dimension_part.maxCoeff(), 4e-6);
  const auto report = EvaluateCylindricalSms(part, s);
  EXPECT_TRUE(report.Find("size")->pass);
}

TEST(CylindricalVariationGenerator, RadialLimitKeepsEveryCellInTheHalfTolerance) {
  const PartSpec part = PaperShaft();
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const SkinModelShape s =
        Make(part, seed, TextureMode::kSampled, {SizeDraw::kPerPart, SizeLimit::kRadial, 10});
    EXPECT_GE(s.variation.minCoeff(), -4e-6 - 1e-18);
    EXPECT_LE(s.variation.maxCoeff(), 4e-6 + 1e-18);
  }
}

TEST(CylindricalVariationGenerator, FormWiderThanTheSizeToleranceIsScaledBack) {
  // 20 um roundness on a +-2 um shaft: ovality would break two-point sizes, so the final clamp
  // must scale the form back, and the result still meets everything.
  PartSpec part = Part("p", Role::kInner, 0.02, 0.02, -2e-6, 2e-6);
  part.form.tolerance[FormCharacteristic::kRoundness] = 20e-6;
  int scaled = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const SkinModelShape s = Make(part, seed, TextureMode::kExpected);
    scaled += s.scaled_back_cells > 0;
    EXPECT_TRUE(EvaluateCylindricalSms(part, s).AllPass()) << seed;
  }
  EXPECT_GT(scaled, 0);
}

TEST(CylindricalVariationGenerator, RegeneratesThenScalesBackAComponentThatFailsAnotherCheck) {
  // A displaced circle is not a perfect limacon: an axis bow of e adds e^2/2R (~1e-9 m here) of
  // roundness, which a zero roundness tolerance refuses. Every redraw fails, and the last resort
  // scales the bow back until roundness passes.
  PartSpec part = Part("p", Role::kInner, 0.02, 0.04, -20e-6, 20e-6);
  part.form.tolerance[FormCharacteristic::kAxisStraightness] = 40e-6;
  part.form.tolerance[FormCharacteristic::kRoundness] = 0.0;
  const SkinModelShape s = Make(part, 4, TextureMode::kExpected);
  EXPECT_EQ(s.regenerations, GeneratorOptions{}.max_regenerations);
  const auto report = EvaluateCylindricalSms(part, s);
  EXPECT_TRUE(report.AllPass());
  EXPECT_LE(report.Find("roundness")->value, kEvaluationSlack);
}

TEST(CylindricalVariationGenerator, RefusesCharacteristicsACylinderDoesNotHave) {
  PartSpec part = PaperShaft();
  part.form.tolerance[FormCharacteristic::kFlatness] = 1e-6;
  EXPECT_THROW(Make(part, 1, TextureMode::kExpected), UnsupportedError);
  PartSpec inverted = PaperShaft();
  inverted.size.lower_deviation = 1e-6;
  inverted.size.upper_deviation = -1e-6;
  EXPECT_THROW(Make(inverted, 1, TextureMode::kExpected), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
