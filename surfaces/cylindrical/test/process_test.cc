// The statistical process model against its distributions, over thousands of drawn parts: size
// mean and standard deviation, the capability it was given, the scrap rate, and every part still
// meeting its drawing.
#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/cylindrical/sms_conformance.h"
#include "surfaces/cylindrical/process_model.h"
#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/cylindrical_generator.h"
#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical {
namespace {

using testing::Part;

// Standard normal distribution function.
double Phi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

struct Sample {
  double mean = 0.0, sd = 0.0;
  long rejections = 0;
  int parts = 0;
  bool all_conform = true;
};

// Draws `parts` parts in sequence from one generator, as a run of a machine would.
Sample Draw(const PartSpec& part, int parts, std::uint64_t seed) {
  Resolution coarse;
  coarse.rows = 6;
  coarse.columns = 24;
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, coarse);
  const CylindricalVariationGenerator generator;
  Rng rng(seed);
  Sample s;
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < parts; ++k) {
    const SkinModelShape sms = generator.Generate(part, grid, TextureMode::kExpected, rng);
    const double d = 2.0 * sms.dimension_part(0);  // actual size, diametral deviation
    sum += d;
    sum2 += d * d;
    s.rejections += sms.rejections;
    s.all_conform = s.all_conform && EvaluateCylindricalSms(part, sms).AllPass();
  }
  s.parts = parts;
  s.mean = sum / parts;
  s.sd = std::sqrt(sum2 / parts - s.mean * s.mean);
  return s;
}

TEST(SizeLaw, CapabilityIndicesPlaceTheMean) {
  ProcessSpec p;
  p.kind = ProcessKind::kStatistical;
  // Cp = Cpk = 1.33: centred, sigma = T / 8.
  NormalLaw law = SizeLaw(p, -8.0, 8.0, Role::kInner);
  EXPECT_NEAR(law.mean, 0.0, 1e-12);
  EXPECT_NEAR(law.sd, 2.0, 1e-12);
  p.cpk = 1.0;  // 3 sigma from the maximum material limit: a shaft's upper, a bore's lower
  law = SizeLaw(p, 0.0, 16.0, Role::kInner);
  EXPECT_NEAR(law.mean, 10.0, 1e-12);
  law = SizeLaw(p, 0.0, 16.0, Role::kOuter);
  EXPECT_NEAR(law.mean, 6.0, 1e-12);
  p.lean = ProcessLean::kLeastMaterial;
  EXPECT_NEAR(SizeLaw(p, 0.0, 16.0, Role::kInner).mean, 6.0, 1e-12);
  p.cpk = 1.5;  // Cpk above Cp is impossible
  EXPECT_THROW(SizeLaw(p, 0.0, 16.0, Role::kInner), UserError);
}

TEST(FormUtilisation, RayleighWithTheGivenOneSidedCapability) {
  ProcessSpec p;
  p.kind = ProcessKind::kStatistical;
  Rng rng(5);
  int rejections = 0;
  const int n = 20000;
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = DrawFormUtilisation(p, rng, &rejections);
    ASSERT_GE(r, 0.0);
    ASSERT_LT(r, 1.0);
    sum += r;
    sum2 += r * r;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  const double s = FormRayleighScale(1.0, p.form_cpk);
  EXPECT_NEAR(mean, s * std::sqrt(M_PI / 2.0), 4.0 * sd / std::sqrt(n));
  EXPECT_NEAR(sd, s * std::sqrt((4.0 - M_PI) / 2.0), 0.03 * sd);
  EXPECT_NEAR((1.0 - mean) / (3.0 * sd), 4.0 / 3.0, 0.05);
  // At Cpk 1.33 the tail beyond the tolerance is exp(-1 / 2 s^2) ~ 6e-4: a handful of rejects.
  const double tail = std::exp(-1.0 / (2.0 * s * s));
  EXPECT_NEAR(static_cast<double>(rejections) / n, tail, 4.0 * std::sqrt(tail / n));
}

TEST(StatisticalProcess, SizeIsNormalWithTheGivenCapability) {
  // No form: the size law alone. Cp = Cpk = 1.33 on a js6-like -6.5/+6.5 um shaft.
  PartSpec part = Part("shaft", Role::kInner, 0.02, 0.02, -6.5e-6, 6.5e-6);
  part.process.kind = ProcessKind::kStatistical;
  const Sample s = Draw(part, 4000, 17);
  const double sigma = 13e-6 / (6.0 * 4.0 / 3.0);
  EXPECT_NEAR(s.mean, 0.0, 4.0 * sigma / std::sqrt(4000.0));
  EXPECT_NEAR(s.sd, sigma, 0.05 * sigma);
  EXPECT_LE(s.rejections, 10);  // 63 ppm expected: 0.25 of 4000
  EXPECT_TRUE(s.all_conform);
}

TEST(StatisticalProcess, ScrapRateOfAnIncapableProcess) {
  // Cp = Cpk = 0.8: a part leaves its limits with probability 2 Phi(-2.4) = 1.64 %.
  PartSpec part = Part("shaft", Role::kInner, 0.02, 0.02, -6.5e-6, 6.5e-6);
  part.process.kind = ProcessKind::kStatistical;
  part.process.cp = part.process.cpk = 0.8;
  const int n = 4000;
  const Sample s = Draw(part, n, 23);
  const double p = 2.0 * Phi(-2.4);
  // Rejections per accepted part follow a geometric law: mean p / (1 - p).
  const double per_part = static_cast<double>(s.rejections) / n;
  EXPECT_NEAR(per_part, p / (1.0 - p), 4.0 * std::sqrt(p / n) / (1.0 - p));
  EXPECT_TRUE(s.all_conform);  // the scrap never reaches the assembly
}

TEST(StatisticalProcess, FormWellInsideItsToleranceAndEveryPartConforms) {
  // The paper's shaft under a capable process: its roundness uses on average about a third of
  // the tolerance (Rayleigh mean at form Cpk 1.33: 0.324 t), never more than all of it.
  PartSpec part = testing::PaperShaft();
  part.process.kind = ProcessKind::kStatistical;
  Resolution coarse;
  coarse.rows = 8;
  coarse.columns = 36;
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, coarse);
  const CylindricalVariationGenerator generator;
  Rng rng(31);
  const double t = part.form.tolerance.at(FormCharacteristic::kRoundness);
  double most_used_sum = 0.0;
  const int n = 300;
  for (int k = 0; k < n; ++k) {
    const SkinModelShape sms = generator.Generate(part, grid, TextureMode::kExpected, rng);
    const ConformanceReport report = EvaluateCylindricalSms(part, sms);
    ASSERT_TRUE(report.AllPass()) << "part " << k;
    double most = 0.0;
    for (const auto& [c, tol] : part.form.tolerance) {
      const auto* item = report.Find(ToString(c));
      ASSERT_NE(item, nullptr);
      most = std::max(most, item->value / tol);
    }
    most_used_sum += most;
  }
  // The most used characteristic is the one scaled to its drawn fraction, so the mean of the
  // largest fraction over several characteristics is at least the Rayleigh mean.
  const double rayleigh_mean = FormRayleighScale(1.0, 4.0 / 3.0) * std::sqrt(M_PI / 2.0);
  EXPECT_GT(most_used_sum / n, 0.8 * rayleigh_mean);
  EXPECT_LT(most_used_sum / n, 0.75);  // the paper's draws sit near the full tolerance
  (void)t;
}

TEST(StatisticalProcess, PerCellSizeDrawIsRefused) {
  PartSpec part = testing::PaperShaft();
  part.process.kind = ProcessKind::kStatistical;
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, {});
  GeneratorOptions options;
  options.size_draw = SizeDraw::kPerCell;
  Rng rng(1);
  EXPECT_THROW(CylindricalVariationGenerator(options).Generate(part, grid, TextureMode::kExpected,
                                                               rng),
               UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
