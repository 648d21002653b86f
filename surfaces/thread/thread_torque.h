#pragma once

#include <vector>

namespace fitfeel::thread {

// Tightening torque of a thread and of a bearing face per unit axial force (T/F, metres), in the
// closed forms of VDI 2230 Part 1 (2015) and as an exact integral over the helicoid flank: an
// oracle, independent of any discretization, for a contact model that sums cell forces.
//
// The split: `lead` is P / (2 pi), the part of T/F whose work (torque times angle) is the
// force's work along the advance; `friction` is the rest, dissipated. A frictionless thread has
// T/F = lead exactly, whatever its flank angle or band.
struct TorqueRatio {
  double total;
  double lead;
  double friction;

  double efficiency() const { return lead / total; }
};

// VDI 2230: M_G / F = (d2/2) tan(phi + rho'), tan phi = P / (pi d2), tan rho' = mu / cos(alpha/2)
// (alpha the flank angle, 60 deg for ISO metric threads).
TorqueRatio VdiThreadTorqueRatio(double pitch_diameter, double pitch, double flank_angle,
                                 double friction);
// VDI 2230's small-angle form for 60 deg threads, M_G / F = 0.16 P + 0.58 d2 mu (lead 0.16 P).
TorqueRatio VdiThreadTorqueRatioApproximate(double pitch_diameter, double pitch, double friction);

// The exact ratio for contact on a single helix of radius r (the band integral's thin-band
// limit): the classic screw formula
//   T/F = r (tan lambda + mu / cos alpha_n) / (1 - mu tan lambda / cos alpha_n),
// tan lambda = P / (2 pi r), tan alpha_n = tan(alpha/2) cos lambda (the flank half-angle in the
// plane normal to the helix). VDI's tan(phi + rho') at r = d2/2 takes alpha_n = alpha/2.
TorqueRatio SingleRadiusTorqueRatio(double radius, double pitch, double flank_angle,
                                    double friction);

// How the flank pressure varies over the band. kWinkler: a rigid nut displaced axially by u
// against the flank, pressure proportional to the normal interference u |n_y(r)|. kUniform: one
// pressure over the band.
enum class FlankPressure { kWinkler, kUniform };

// T/F of a nut turned against the loaded flank y = c theta + P/4 - k (r - r_p) between radii
// inner_radius and outer_radius (c = P / (2 pi), k = tan(alpha/2)), friction mu opposing the
// sliding along the helix; the r-integrals by Gauss-Legendre quadrature of `points` nodes (the
// theta-integral only multiplies both by the turned angle). docs/threads.md derives the
// integrands.
TorqueRatio HelicoidTorqueRatio(double pitch, double flank_angle, double inner_radius,
                                double outer_radius, double friction, FlankPressure pressure,
                                int points = 24);

// Bearing face (head or nut on the clamped part), annulus between the hole d_h and the bearing
// diameter d_W: VDI 2230's M_K / F = mu_K D_Km / 2 with D_Km = (d_W + d_h) / 2 ...
double VdiBearingTorqueRatio(double bearing_diameter, double hole_diameter, double friction);
// ... and the exact ratio under uniform pressure, mu_K (2/3) (R^3 - r^3) / (R^2 - r^2), R = d_W/2,
// r = d_h/2, never below VDI's mean radius.
double UniformAnnulusTorqueRatio(double bearing_diameter, double hole_diameter, double friction);

// VDI 2230's tightening torque M_A = F (0.16 P + 0.58 d2 mu_G + mu_K D_Km / 2) of an ISO metric
// bolt of nominal diameter d and pitch P, N m.
double VdiTighteningTorque(double nominal_diameter, double pitch, double preload,
                           double thread_friction, double bearing_diameter, double hole_diameter,
                           double bearing_friction);

// Gauss-Legendre rule of n nodes on [-1, 1] (exact for polynomials of degree up to 2n - 1).
struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};
QuadratureRule GaussLegendreRule(int points);

}  // namespace fitfeel::thread
