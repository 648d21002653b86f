#include "framework/model/hub_axial_coupling.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/model/test/steel_pair.h"

namespace fitfeel {
namespace {

using test_support::SteelPair;

TEST(HubAxialCoupling, FoundationIsTheHubsLameTermAndRigidityTheShells) {
  const HubAxialCoupling c(SteelPair(), 0.5e-3, 40);
  // a = 10, b = 15 mm: k = E / (a ((b^2 + a^2)/(b^2 - a^2) + nu)) = 210 GPa / (10 mm * 2.9).
  EXPECT_NEAR(c.foundation(), 210e9 / (10e-3 * 2.9), 1e-9 * c.foundation());
  // D = E t^3 / (12 (1 - nu^2)), t = 5 mm, referred to the bore by R / a = 12.5 / 10.
  EXPECT_NEAR(c.rigidity(), 210e9 * 125e-9 / (12 * 0.91) * 1.25, 1e-9 * c.rigidity());
  EXPECT_EQ(c.rows(), 40);
}

TEST(HubAxialCoupling, AUniformPressureBendsNothing) {
  const HubAxialCoupling c(SteelPair(), 0.5e-3, 40);
  std::vector<double> p(40, 30e6), out(40);
  c.ExtraDisplacement(p.data(), out.data());
  // To rounding of F p - p / k (each about 5 um).
  for (double x : out) EXPECT_NEAR(x, 0.0, 1e-9 * 30e6 / c.foundation());
  // Symmetric (Maxwell-Betti) and a pressure's extra displacement on its own row is negative:
  // the neighbours carry part of it.
  EXPECT_LT((c.matrix() - c.matrix().transpose()).cwiseAbs().maxCoeff(),
            1e-12 * c.matrix().cwiseAbs().maxCoeff());
  for (int i = 0; i < 40; ++i) EXPECT_LT(c.matrix()(i, i), 0.0);
}

// Hetenyi's beam on an elastic foundation (Beams on Elastic Foundation, 1946; Timoshenko, Strength
// of Materials II): an infinite beam under a uniform load p over x < 0 deflects p / (2k) at the
// load's edge and p / (2k) e^(-beta x) cos(beta x) beyond it, beta = (k / (4 D))^(1/4). A hub
// 200 mm long (16 / beta) loaded on its first half is that beam away from its ends.
TEST(HubAxialCoupling, HalfLoadedLongHubIsHetenyisBeam) {
  const int rows = 400;
  const double pitch = 0.5e-3;
  const HubAxialCoupling c(SteelPair(), pitch, rows);
  const double k = c.foundation(), beta = std::pow(k / (4.0 * c.rigidity()), 0.25);
  const double p0 = 10e6;
  std::vector<double> p(rows, 0.0), extra(rows);
  for (int i = 0; i < rows / 2; ++i) p[static_cast<std::size_t>(i)] = p0;
  c.ExtraDisplacement(p.data(), extra.data());
  const double scale = p0 / k;
  for (int i = rows / 2 - 40; i < rows / 2 + 60; ++i) {
    const double x = (i + 0.5) * pitch - 0.5 * rows * pitch;  // from the load's edge
    const double w = extra[static_cast<std::size_t>(i)] + p[static_cast<std::size_t>(i)] / k;
    const double bx = beta * std::abs(x);
    const double tail = 0.5 * scale * std::exp(-bx) * std::cos(bx);
    const double expected = x > 0.0 ? tail : scale - tail;  // symmetric about the edge
    // Central differences on rows 0.5 mm apart with 1 / beta = 6.2 mm: O((beta h)^2).
    EXPECT_NEAR(w, expected, 0.01 * scale) << "x = " << x;
  }
}

TEST(HubAxialCoupling, RefusesWhatItCannotModel) {
  PressFitSection bad = SteelPair();
  bad.d2 = bad.d1;
  EXPECT_THROW(HubAxialCoupling(bad, 0.5e-3, 10), UserError);
  EXPECT_THROW(HubAxialCoupling(SteelPair(), 0.0, 10), UserError);
  EXPECT_THROW(HubAxialCoupling(SteelPair(), 0.5e-3, 0), UserError);
}

}  // namespace
}  // namespace fitfeel
