#include "framework/safety/virtual_coupling.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "framework/device/device_specs.h"

namespace fitfeel {
namespace {

TEST(CouplingGains, DefaultsObeyThePassivityBoundForEveryKnownDeviceAndRate) {
  for (const DeviceSpec& spec : KnownDeviceSpecs()) {
    for (double rate : {100.0, 250.0, 500.0, 1000.0, 2000.0, 4000.0}) {
      const double period = 1.0 / rate;
      const CouplingGains gains = DefaultCouplingGains(spec, period);
      EXPECT_GT(gains.stiffness, 0.0);
      EXPECT_GE(gains.damping, 0.0);
      EXPECT_LE(gains.stiffness, spec.max_stiffness) << spec.model << " " << rate;
      // b > K_c T / 2 + |B_c| (Colgate & Schenkel), with margin.
      EXPECT_GT(spec.damping, gains.stiffness * period / 2.0 + gains.damping) << spec.model;
      EXPECT_TRUE(CouplingGainsArePassive(gains, spec, period));
    }
  }
}

TEST(CouplingGains, DesktopAtOneKilohertz) {
  // K_c = 0.8 * 1000 N/m; B_c = 0.5 * (5 - 800 * 0.001 / 2) = 2.3 N*s/m.
  const CouplingGains gains = DefaultCouplingGains(LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
  EXPECT_DOUBLE_EQ(gains.stiffness, 800.0);
  EXPECT_DOUBLE_EQ(gains.damping, 2.3);
}

TEST(CouplingGains, BoundRejectsGainsOnBothSides) {
  const DeviceSpec touch = LookupDeviceSpec("Touch");                 // 400 N/m, 4 N*s/m
  EXPECT_FALSE(CouplingGainsArePassive({500.0, 0.0}, touch, 1e-3));   // above max stiffness
  EXPECT_FALSE(CouplingGainsArePassive({400.0, 3.81}, touch, 1e-3));  // 0.2 + 3.81 > 4
  EXPECT_TRUE(CouplingGainsArePassive({400.0, 3.79}, touch, 1e-3));
  // At 100 Hz the spring alone takes K T / 2 = 2: less damping room.
  EXPECT_FALSE(CouplingGainsArePassive({400.0, 2.1}, touch, 1e-2));
}

// Device handle held 5 mm inside a wall at x = 0 of stiffness k_e (device units): the proxy must
// settle where the coupling spring and the wall balance, without oscillating, whatever k_e.
void ExpectSettlesAgainstWall(double wall_stiffness, bool give_hint) {
  const CouplingGains gains{800.0, 2.3};
  VirtualCoupling coupling;
  coupling.Configure(gains, 0.0);
  const Eigen::Vector3d device(0.005, 0.0, 0.0);
  coupling.Reset(Eigen::Vector3d(-0.001, 0, 0), Eigen::Vector3d::Zero());
  Eigen::Vector3d force_on_device;
  for (int k = 0; k < 2000; ++k) {
    const double x = coupling.proxy_position().x();
    const Eigen::Vector3d wall(-wall_stiffness * std::max(0.0, x), 0.0, 0.0);
    force_on_device = coupling.Step(wall, device, Eigen::Vector3d::Zero(),
                                    give_hint && x > 0.0 ? wall_stiffness : 0.0, 1e-3);
    ASSERT_TRUE(force_on_device.allFinite());
    ASSERT_LT(std::abs(coupling.proxy_position().x()), 0.01) << "k " << k;
  }
  const double series = gains.stiffness * wall_stiffness / (gains.stiffness + wall_stiffness);
  // With the hint the implicit step is exact for a linear wall; the secant estimate alone is
  // exact once two samples lie in contact, which the settling reaches.
  const double tolerance = give_hint ? 1e-9 : 1e-6;
  EXPECT_NEAR(force_on_device.x(), -series * 0.005, tolerance * series * 0.005)
      << "wall " << wall_stiffness << " hint " << give_hint;
  EXPECT_NEAR(coupling.proxy_position().x(),
              gains.stiffness * 0.005 / (gains.stiffness + wall_stiffness), 1e-9)
      << "wall " << wall_stiffness << " hint " << give_hint;
}

TEST(VirtualCoupling, SettlesAgainstStiffWallsWithAndWithoutAHint) {
  for (double k : {1e2, 1e3, 2e4, 2e6, 2e8, 2e10}) {
    ExpectSettlesAgainstWall(k, true);
    ExpectSettlesAgainstWall(k, false);
  }
}

TEST(VirtualCoupling, ProxyFollowsTheHandInFreeSpace) {
  VirtualCoupling coupling;
  coupling.Configure({800.0, 2.3}, 0.0);
  coupling.Reset(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, -0.01, 0));
  const Eigen::Vector3d v(0.0, -0.01, 0.0);  // 10 mm/s
  Eigen::Vector3d f;
  for (int k = 1; k <= 1000; ++k) {
    f = coupling.Step(Eigen::Vector3d::Zero(), v * (k * 1e-3), v, 0.0, 1e-3);
  }
  EXPECT_LT(f.norm(), 1e-12);
  EXPECT_NEAR((coupling.proxy_position() - v).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace fitfeel
