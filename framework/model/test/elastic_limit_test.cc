#include "framework/model/elastic_limit.h"

#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

// DIN 7190 hub at Q = 2/3 (d 20 mm in D 30 mm): 0.321 R_e; C45 +QT, R_e = 430 MPa for 16-40 mm
// (EN 10083-2): about 138 MPa, which the Lame pressure of 5.8333 MPa/um (steel, solid shaft)
// reaches at about 23.6 um of radial interference.
TEST(ElasticLimit, HubAtTwoThirdsMatchesDin7190) {
  const double p = HubYieldPressure(20e-3, 30e-3, 430e6);
  EXPECT_NEAR(p / 430e6, 0.3208, 1e-4);
  EXPECT_NEAR(p, 138e6, 0.5e6);
  EXPECT_NEAR(p / 5.8333e12 * 1e6, 23.6, 0.05);
}

// The DIN form is the von Mises stress at the bore with the axial stress midway between the
// radial and hoop stresses of Lame's solution: check it from the stresses themselves.
TEST(ElasticLimit, HubFormIsTheBoreStressOfLame) {
  const double d = 8.2e-3, big_d = 24e-3, p = 100e6;
  const double q2 = (d / big_d) * (d / big_d);
  const double hoop = p * (1.0 + q2) / (1.0 - q2), radial = -p;
  const double mid = 0.5 * (hoop + radial);
  const double s1 = hoop - radial, s2 = radial - mid, s3 = mid - hoop;
  const double von_mises = std::sqrt(0.5 * (s1 * s1 + s2 * s2 + s3 * s3));
  EXPECT_NEAR(HubYieldPressure(d, big_d, 430e6) / 430e6, p / von_mises, 1e-12);
}

TEST(ElasticLimit, SolidShaftYieldsAtItsYieldStrengthHollowAtItsBore) {
  EXPECT_DOUBLE_EQ(ShaftYieldPressure(20e-3, 0.0, 430e6), 430e6);
  EXPECT_NEAR(ShaftYieldPressure(20e-3, 10e-3, 430e6), 0.75 * 430e6 / std::sqrt(3.0), 1.0);
  EXPECT_DOUBLE_EQ(HertzYieldPeakPressure(1000e6), 1610e6);
}

TEST(ElasticLimit, RefusesDiametersThatDoNotNest) {
  EXPECT_THROW(HubYieldPressure(30e-3, 20e-3, 430e6), UserError);
  EXPECT_THROW(HubYieldPressure(20e-3, 30e-3, 0.0), UserError);
  EXPECT_THROW(ShaftYieldPressure(20e-3, 20e-3, 430e6), UserError);
}

}  // namespace
}  // namespace fitfeel
