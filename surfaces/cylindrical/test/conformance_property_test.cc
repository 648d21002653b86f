// Property test: over many seeds and several specifications, every
// generated skin model shape meets every tolerance it came from, as evaluated independently by
// framework/metrology (two-point sizes, minimum-zone roundness and cylindricity, axis and
// generatrix straightness).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "surfaces/cylindrical/sms_conformance.h"
#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/cylindrical_generator.h"
#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical {
namespace {

using testing::Part;

struct Case {
  std::string name;
  PartSpec part;
  int seeds;
  TextureMode texture = TextureMode::kExpected;
  GeneratorOptions options = {};
};

PartSpec WithForm(PartSpec p, double axis, double generatrix, double roundness,
                  double cylindricity) {
  if (axis >= 0) p.form.tolerance[FormCharacteristic::kAxisStraightness] = axis;
  if (generatrix >= 0) p.form.tolerance[FormCharacteristic::kGeneratrixStraightness] = generatrix;
  if (roundness >= 0) p.form.tolerance[FormCharacteristic::kRoundness] = roundness;
  if (cylindricity >= 0) p.form.tolerance[FormCharacteristic::kCylindricity] = cylindricity;
  return p;
}

std::vector<Case> Cases() {
  constexpr double um = 1e-6, mm = 1e-3;
  const double none = -1.0;
  std::vector<Case> cases;
  // Paper Table 2, both texture modes.
  cases.push_back({"paper shaft js6", testing::PaperShaft(), 200});
  cases.push_back({"paper hole", testing::PaperHole(), 200});
  cases.push_back(
      {"paper shaft js6 sampled texture", testing::PaperShaft(), 100, TextureMode::kSampled});
  cases.push_back({"paper hole sampled texture", testing::PaperHole(), 100, TextureMode::kSampled});
  // H7/g6 at 20 mm (ISO 286: H7 0/+21, g6 -20/-7 um) with every cylinder characteristic.
  cases.push_back({"H7 hole",
                   WithForm(Part("h", Role::kOuter, 20 * mm, 20 * mm, 0, 21 * um), 8 * um, 6 * um,
                            6 * um, 10 * um),
                   60});
  cases.push_back({"g6 shaft",
                   WithForm(Part("s", Role::kInner, 20 * mm, 40 * mm, -20 * um, -7 * um), 5 * um,
                            4 * um, 4 * um, 6 * um),
                   60});
  // Tight: a 1 um roundness, 2 um cylindricity gauge pin; loose: a rough 50 mm bore.
  cases.push_back({"tight pin",
                   WithForm(Part("p", Role::kInner, 8 * mm, 25 * mm, -2 * um, 2 * um), 2 * um,
                            1 * um, 1 * um, 2 * um),
                   60});
  cases.push_back({"loose bore",
                   WithForm(Part("b", Role::kOuter, 50 * mm, 70 * mm, 80 * um, 240 * um), 50 * um,
                            40 * um, 30 * um, 60 * um),
                   40, TextureMode::kSampled});
  // Cylindricity alone bounds every component; a part shorter than one form wave.
  cases.push_back({"cylindricity only",
                   WithForm(Part("c", Role::kInner, 30 * mm, 45 * mm, -10 * um, 10 * um), none,
                            none, none, 8 * um),
                   60});
  cases.push_back(
      {"short sleeve",
       WithForm(Part("s", Role::kOuter, 12 * mm, 8 * mm, 0, 18 * um), 10 * um, none, 8 * um, none),
       60});
  // The alternatives: literal radial limits (eq. 2) with per-part size.
  cases.push_back({"paper shaft radial limits",
                   testing::PaperShaft(),
                   60,
                   TextureMode::kSampled,
                   {SizeDraw::kPerPart, SizeLimit::kRadial, 10}});
  return cases;
}

TEST(CylindricalConformance, EveryShapeMeetsEveryToleranceItCameFrom) {
  for (const Case& c : Cases()) {
    const SurfaceGrid grid = CylindricalDiscretizer().Discretize(c.part, {});
    const CylindricalVariationGenerator generator(c.options);
    int failures = 0;
    for (int seed = 1; seed <= c.seeds; ++seed) {
      Rng rng(seed);
      const SkinModelShape sms = generator.Generate(c.part, grid, c.texture, rng);
      const ConformanceReport report = EvaluateCylindricalSms(c.part, sms);
      for (const auto& item : report.items) {
        if (item.pass) continue;
        if (++failures > 5) break;
        ADD_FAILURE() << c.name << " seed " << seed << ": " << item.name << " " << item.value_low
                      << " .. " << item.value << " outside " << item.limit_low << " .. "
                      << item.limit_high;
      }
      if (c.options.size_limit == SizeLimit::kRadial) {
        EXPECT_GE(sms.variation.minCoeff(), c.part.size.lower_deviation / 2 - 1e-12);
        EXPECT_LE(sms.variation.maxCoeff(), c.part.size.upper_deviation / 2 + 1e-12);
      }
    }
    EXPECT_EQ(failures, 0) << c.name;
  }
}

TEST(CylindricalConformance, PerCellSizeMeetsTheSizeLimits) {
  // The literal per-cell reading: size limits hold; its noise is form error, so form tolerances
  // tighter than the size tolerance are not promised (README).
  const PartSpec part = testing::PaperShaft();
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, {});
  const CylindricalVariationGenerator generator({SizeDraw::kPerCell, SizeLimit::kTwoPoint, 10});
  for (int seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    const SkinModelShape sms = generator.Generate(part, grid, TextureMode::kSampled, rng);
    EXPECT_TRUE(EvaluateCylindricalSms(part, sms).Find("size")->pass) << seed;
  }
}

TEST(CylindricalConformance, FormIsNotTriviallyZero) {
  // The property above would hold for a generator that returned perfect cylinders: check that
  // the shapes use a fair part of their tolerances.
  const PartSpec part = testing::PaperHole();
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, {});
  const CylindricalVariationGenerator generator;
  double roundness = 0.0, axis = 0.0;
  const int seeds = 30;
  for (int seed = 1; seed <= seeds; ++seed) {
    Rng rng(seed);
    const SkinModelShape sms = generator.Generate(part, grid, TextureMode::kExpected, rng);
    const auto report = EvaluateCylindricalSms(part, sms);
    roundness += report.Find("roundness")->value / seeds;
    axis += report.Find("axis_straightness")->value / seeds;
  }
  EXPECT_GT(roundness, 3e-6);  // of 10 um
  EXPECT_GT(axis, 3e-6);       // of 10 um
}

}  // namespace
}  // namespace fitfeel::cylindrical
