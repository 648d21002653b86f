// Properties on random surfaces (which also exercise the LP solver on degenerate-free and
// near-degenerate data): every minimum zone is no wider than a feasible zone, and the
// characteristics nest as ISO defines them (a section of the cylindricity zone is a roundness
// zone; a generatrix lies in its axial section).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "framework/metrology/circle_fit.h"
#include "framework/metrology/cylinder_form.h"

namespace fitfeel::metrology {
namespace {

CylinderSamples RandomSurface(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> rows(3, 30), half_columns(4, 40), harmonic(1, 8);
  CylinderSamples s;
  s.nominal_radius = 0.005 + 0.02 * (u(rng) + 1.0);
  const int m = rows(rng), n = 2 * half_columns(rng);
  const double length = 0.01 + 0.05 * (u(rng) + 1.0);
  s.y = Eigen::VectorXd::LinSpaced(m, 0.0, length);
  s.theta.resize(n);
  for (int j = 0; j < n; ++j) s.theta(j) = 2.0 * std::numbers::pi * j / n;
  s.deviation = Eigen::MatrixXd::Zero(m, n);
  // Axis bow, lobes, taper and noise, each a few micrometres.
  const int terms = 1 + harmonic(rng) % 4;
  for (int t = 0; t < terms; ++t) {
    const int k = harmonic(rng);
    const double a = 3e-6 * u(rng), phase = 3.0 * u(rng), w = 2.0 * u(rng);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j)
        s.deviation(i, j) += a * std::cos(k * s.theta(j) + phase) * std::cos(w * s.y(i) / length);
  }
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) s.deviation(i, j) += 1e-6 * u(rng);
  return s;
}

TEST(MetrologyProperties, MinimumZonesNestAndBeatFeasibleZones) {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 150; ++trial) {
    const CylinderSamples s = RandomSurface(rng);
    const double cylindricity = MinimumZoneCylindricity(s).value;
    const double about_nominal = s.deviation.maxCoeff() - s.deviation.minCoeff();
    EXPECT_LE(cylindricity, about_nominal + 1e-12) << trial;
    double worst_round = 0.0;
    for (int i = 0; i < s.y.size(); ++i) {
      const Eigen::Matrix2Xd p = s.SectionPoints(i);
      const RoundnessResult r = MinimumZoneRoundness(p);
      const Circle ls = LeastSquaresCircle(p);
      const Eigen::VectorXd d = (p.colwise() - ls.centre).colwise().norm();
      EXPECT_LE(r.value, d.maxCoeff() - d.minCoeff() + 1e-12) << trial;
      worst_round = std::max(worst_round, r.value);
    }
    // Linearisation differences are ~e^2/2R: far below 1e-10 m for micrometre deviations.
    EXPECT_LE(worst_round, cylindricity + 1e-10) << trial;
    EXPECT_LE(EvaluateCylinderForm(FormCharacteristic::kGeneratrixStraightness, s),
              cylindricity + 1e-10)
        << trial;
    const double axis = AxisStraightness(s.y, SectionCentres(s));
    EXPECT_GE(axis, 0.0);
    EXPECT_TRUE(std::isfinite(axis));
  }
}

}  // namespace
}  // namespace fitfeel::metrology
