#include "surfaces/cylindrical/elastic/harmonic_compliance.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/cylindrical/test/steel_pair.h"

namespace fitfeel::cylindrical {
namespace {

using testing::SteelPair;

TEST(HarmonicCompliance, BreathingModeIsLame) {
  // Lame, solid shaft d1 = 20 in a hub d2 = 30, steel: 5.8333 MPa per um of radial interference.
  EXPECT_NEAR(1.0 / HarmonicCompliance(SteelPair(), 0), 5.8333e12, 5e8);
}

TEST(HarmonicCompliance, MichellStiffnessPerHarmonic) {
  // K_n / P0 for the same pair in plane stress: independent values 0.145, 0.78, 3.15, 8.8.
  const PressFitSection s = SteelPair();
  const double p0 = 1.0 / HarmonicCompliance(s, 0);
  const struct {
    int n;
    double ratio, tol;
  } rows[] = {{2, 0.145, 0.0015}, {3, 0.78, 0.008}, {5, 3.15, 0.02}, {10, 8.8, 0.06}};
  for (const auto& r : rows) {
    EXPECT_NEAR(1.0 / HarmonicCompliance(s, r.n) / p0, r.ratio, r.tol) << "n = " << r.n;
  }
}

TEST(HarmonicCompliance, AgreesWithCalculixWithinTwoPercent) {
  // tools/fem/data/harmonic.csv: CalculiX, quadratic plane-stress elements, pressure cos(n theta)
  // on the shaft's rim and the hub's bore (order 1 balanced by a uniform body force in each, its
  // faces' motion taken relative to each body's centroid).
  std::ifstream in(std::string(FITFEEL_TEST_SOURCE_DIR) + "/tools/fem/data/harmonic.csv");
  ASSERT_TRUE(in) << "tools/fem/data/harmonic.csv";
  const PressFitSection s = SteelPair();
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'n') continue;
    std::stringstream ss(line);
    std::string n, k, ratio;
    std::getline(ss, n, ',');
    std::getline(ss, k, ',');
    std::getline(ss, ratio, ',');
    const double michell = 1.0 / HarmonicCompliance(s, std::stoi(n));
    const double fem = std::stod(k) * 1e12;  // MPa/um -> Pa/m
    std::printf("n = %2s: Michell K_n/P0 = %.5f, FEM %.5f (%+.2f %%)\n", n.c_str(),
                michell / (1.0 / HarmonicCompliance(s, 0)), std::stod(ratio),
                100.0 * (fem / michell - 1.0));
    EXPECT_NEAR(fem / michell, 1.0, 0.02) << "n = " << n;
    ++checked;
  }
  EXPECT_EQ(checked, 6);  // n = 0, 1, 2, 3, 5, 10
}

TEST(HarmonicCompliance, HighOrdersTendToTwoHalfSpaces) {
  // Pressure cos(n theta) on an elastic half-space closes 2 p a / (E n) per body (plane stress).
  const PressFitSection s = SteelPair();
  const double a = 0.01;
  for (int n : {200, 400}) {
    const double half_spaces = 4.0 * a / (210e9 * n);
    EXPECT_NEAR(HarmonicCompliance(s, n) / half_spaces, 1.0, 2.0 / n) << n;
  }
  PressFitSection strain = s;
  strain.plane_strain = true;
  EXPECT_NEAR(HarmonicCompliance(strain, 300) / (4.0 * a * (1 - 0.09) / (210e9 * 300)), 1.0, 0.01);
}

TEST(HarmonicCompliance, StifferWithThickerHubAndSofterWithHollowShaft) {
  PressFitSection s = SteelPair();
  const double base = HarmonicCompliance(s, 2);
  s.d2 = 0.060;
  EXPECT_LT(HarmonicCompliance(s, 2), base);
  s = SteelPair();
  s.di = 0.010;
  EXPECT_GT(HarmonicCompliance(s, 2), base);
}

// Order 1 of a solid disc under p cos(theta) on its rim, balanced by a uniform body force p / a:
// the stress sigma_xx = sigma_yy = -p x / a (no shear) meets equilibrium and the rim's traction,
// so u_x = -(1 - nu) p (x^2 - y^2) / (2 E a), u_y = -(1 - nu) p x y / (E a): the rim moves
// (1 - nu) p a / (2E) cos(theta) towards the centre, whose area-mean motion is nil. With a hub a
// million times stiffer the closure is the shaft's alone (to 3e-6).
TEST(HarmonicCompliance, OrderOneOfASolidShaftIsHalfItsBreathing) {
  PressFitSection s = SteelPair();
  s.hub.youngs_modulus *= 1e6;
  const double a = 0.01, nu = 0.3, e = 210e9;
  EXPECT_NEAR(HarmonicCompliance(s, 1) / ((1.0 - nu) * a / (2.0 * e)), 1.0, 1e-5);
  // The plane-strain constants go through the same formula.
  s.plane_strain = true;
  const double e_strain = e / (1.0 - nu * nu), nu_strain = nu / (1.0 - nu);
  EXPECT_NEAR(HarmonicCompliance(s, 1) / ((1.0 - nu_strain) * a / (2.0 * e_strain)), 1.0, 1e-5);
  // A hollow shaft is softer.
  PressFitSection hollow = SteelPair();
  hollow.di = 0.010;
  EXPECT_GT(HarmonicCompliance(hollow, 1), HarmonicCompliance(SteelPair(), 1));
}

// The parts' shares (what the axial coupling subtracts from its elements) add up to the pair's.
TEST(HarmonicCompliance, RingSharesAddUpToThePairs) {
  for (bool strain : {false, true}) {
    PressFitSection s = SteelPair();
    s.di = 0.008;  // a hollow shaft: both shares are rings
    s.plane_strain = strain;
    for (int n : {1, 2, 3, 5, 10}) {
      const double shaft = RingHarmonicCompliance(0.004, 0.010, false, s.shaft, strain, n);
      const double hub = RingHarmonicCompliance(0.010, 0.015, true, s.hub, strain, n);
      EXPECT_GT(shaft, 0.0) << n;
      EXPECT_GT(hub, 0.0) << n;
      EXPECT_NEAR(shaft + hub, HarmonicCompliance(s, n), 1e-12 * HarmonicCompliance(s, n)) << n;
    }
  }
  EXPECT_THROW(RingHarmonicCompliance(0.0, 0.010, false, SteelPair().shaft, false, 0), UserError);
}

TEST(HarmonicCompliance, RefusesNegativeOrdersAndBadSections) {
  EXPECT_THROW(HarmonicCompliance(SteelPair(), -1), UserError);
  PressFitSection s = SteelPair();
  s.d2 = 0.019;
  EXPECT_THROW(HarmonicCompliance(s, 2), UserError);
}

TEST(Din7190, SmoothingOfTwoRz16Surfaces) {
  // 0.8 (1.6 + 1.6) um on the diameter: 1.28 um radial.
  TextureSpec t{3.2e-6, 0.4e-6, 1.6e-6};
  EXPECT_NEAR(Din7190RadialSmoothing(t, t), 1.28e-6, 1e-15);
}

TEST(PlasticityIndex, GroundSteelYields) {
  const Material steel{"steel", 210e9, 0.3};
  const double e_star = ContactModulus(steel, steel);
  EXPECT_NEAR(e_star, 210e9 / (2 * 0.91), 1e6);
  TextureSpec t{0.0, 0.4e-6, 1.6e-6};
  const double sigma = EquivalentSigmaFromRa(t, t);
  EXPECT_NEAR(sigma, std::sqrt(2.0) * 0.4e-6 * std::sqrt(std::numbers::pi / 2), 1e-12);
  // Hardness 2 GPa (about 200 HV), summit radius 10 um: psi well above 1.
  EXPECT_GT(PlasticityIndex(e_star, 2e9, sigma, 10e-6), 10.0);
}

}  // namespace
}  // namespace fitfeel::cylindrical
