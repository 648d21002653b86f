// The seven shipped 20 mm fits (scenarios/fits-20mm-h7*.yaml) as small studies: their forces rank
// in the order of their interference, and the interference fits' press forces agree with the
// closed form of DIN 7190-1 (thick-walled cylinders, Lame) computed here from the scenes' own
// limits, independently of the model.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/study/study.h"

namespace fitfeel::study {
namespace {

namespace fs = std::filesystem;

// In the order of their mean interference (ISO 286-2 at 20 mm: g6 -7/-20, h6 0/-13, js6 +-6.5,
// k6 +15/+2, n6 +28/+15, p6 +35/+22, s6 +48/+35 um against H7 0/+21).
const std::vector<std::string> kFits = {"g6", "h6", "js6", "k6", "n6", "p6", "s6"};

class Fits20mm : public ::testing::Test {
 protected:
  Fits20mm() : registry_({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"}) { registry_.LoadAll(); }
  static fs::path File(const std::string& fit) {
    return fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / ("fits-20mm-h7" + fit + ".yaml");
  }
  StudyResult Study(const std::string& fit) const {
    StudySettings s;
    s.pairs = 12;
    s.seed = 3;
    s.threads = 2;
    return RunStudy(File(fit), registry_, s);
  }
  PluginRegistry registry_;
};

std::vector<double> Column(const StudyResult& r, double PairResult::*field) {
  std::vector<double> v;
  for (const PairResult& p : r.pairs) v.push_back(p.*field);
  return v;
}

// Press-in force at full engagement by DIN 7190-1 for a solid shaft in a hub of one material:
// effective interference U_w = U - 0.8 (Rz_i + Rz_a) (smoothing), relative xi = U_w / d,
// p = E xi / (K_a + K_i) with K_i = 1 - nu and K_a = (1 + Q^2) / (1 - Q^2) + nu, Q = d / D_a;
// F = mu p pi d L.
double Din7190PressForce(const Scene& scene, double interference) {
  const double d = scene.inner.size.nominal;
  const double q = d / 30e-3;  // the scenes' hub outer diameter
  const double rz = 1.6e-6;    // Rz of both parts in the scenes
  const double nu = scene.inner.material.poisson;
  const double e = scene.inner.material.youngs_modulus;
  const double xi = (interference - 0.8 * (rz + rz)) / d;
  const double p = e * xi / ((1 + q * q) / (1 - q * q) + nu + (1 - nu));
  const double engaged = 20e-3;
  return 0.15 * p * std::numbers::pi * d * engaged;
}

TEST_F(Fits20mm, RankInTheOrderOfTheirInterferenceAndMatchDin7190) {
  std::vector<Distribution> max;
  std::vector<double> interfering;
  for (const std::string& fit : kFits) {
    const StudyResult r = Study(fit);
    ASSERT_EQ(r.pairs.size(), 12u) << fit;
    max.push_back(Describe(Column(r, &PairResult::axial_max_N)));
    int n = 0;
    for (const PairResult& p : r.pairs) n += p.interfering ? 1 : 0;
    interfering.push_back(n / 12.0);
    const Scene scene = LoadScene(File(fit), registry_);
    for (const PairResult& p : r.pairs) {
      ASSERT_TRUE(p.elastic_utilisation_max.has_value()) << fit << ": yield strength given";
      // A capable process stays inside the drawing (scrap is redrawn).
      EXPECT_GE(p.shaft_size_um, scene.inner.size.lower_deviation * 1e6 - 1e-9) << fit;
      EXPECT_LE(p.shaft_size_um, scene.inner.size.upper_deviation * 1e6 + 1e-9) << fit;
    }
  }
  // Clearance fits never interfere; interference fits always do.
  EXPECT_EQ(interfering[0], 0.0);
  EXPECT_EQ(interfering[1], 0.0);
  EXPECT_EQ(interfering[4], 1.0);
  EXPECT_EQ(interfering[5], 1.0);
  EXPECT_EQ(interfering[6], 1.0);
  for (std::size_t k = 1; k < kFits.size(); ++k) {
    EXPECT_GE(interfering[k], interfering[k - 1]) << kFits[k];
    // Sliding fits all sit at the load's friction (2 N x 0.15): equal within 1 %, not lower.
    EXPECT_GE(max[k].p50, 0.99 * max[k - 1].p50) << kFits[k];
  }
  // A sliding fit costs the radial load's friction; a press fit thousands of newtons.
  EXPECT_LT(max[0].p95, 1.0);
  EXPECT_GT(max[5].p50, 1000.0);

  // The interference fits at the mean interference of their limits (centred capable processes):
  // DIN 7190 lies within the spread of the study's largest axial force.
  for (std::size_t k : {5u, 6u}) {
    const Scene scene = LoadScene(File(kFits[k]), registry_);
    const double shaft = scene.inner.size.nominal +
                         (scene.inner.size.lower_deviation + scene.inner.size.upper_deviation) / 2;
    const double hole = scene.outer.size.nominal +
                        (scene.outer.size.lower_deviation + scene.outer.size.upper_deviation) / 2;
    const double din = Din7190PressForce(scene, shaft - hole);
    EXPECT_GE(din, max[k].p5) << kFits[k];
    EXPECT_LE(din, max[k].p95) << kFits[k];
  }
}

}  // namespace
}  // namespace fitfeel::study
