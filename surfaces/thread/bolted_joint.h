#pragma once

#include <cmath>

#include <vector>

namespace fitfeel::thread {

// Bolted-joint engineering after VDI 2230 Part 1 (2015), "Systematic calculation of highly stressed
// bolted joints", for a through-bolted joint (bolt and nut, VDI's "DSV") with an ISO metric thread
// (60 deg flank angle). Everything is in SI units: metres, newtons, pascals; a resilience
// (compliance) is in m/N. Every function checks its arguments and throws UserError naming the
// argument and its value.

// ISO 724 basic diameters of an external ISO metric thread of nominal diameter d and pitch P:
// d2 = d - 0.649519 P (pitch diameter) and d3 = d - 1.226869 P (minor diameter of the bolt).
// Both require 0 < P <= d/3 (ISO 261 pitches stay below d/4).
double PitchDiameter(double nominal_diameter, double pitch);
double MinorDiameter(double nominal_diameter, double pitch);
// ISO 898-1 / VDI 2230 stress cross-section A_S = pi/4 ((d2 + d3)/2)^2.
double StressArea(double nominal_diameter, double pitch);
// Its polar section modulus W_P = pi d_0^3 / 16, d_0 = (d2 + d3)/2 (the torsion of tightening).
double StressSectionModulus(double nominal_diameter, double pitch);

// An unthreaded cylindrical part of the bolt inside the clamp length (a shank, a reduced shank).
struct CylindricalSection {
  double length;
  double diameter;
};

// A bolt with a hexagon head and a nut through clamped parts of total thickness clamp_length
// (l_K). `shank` lists the unthreaded sections inside the clamp length, starting under the head;
// the rest of l_K is free loaded thread. The moduli are the bolt's E_S and the nut's E_M.
struct ThroughBolt {
  double nominal_diameter;
  double pitch;
  double clamp_length;
  std::vector<CylindricalSection> shank;
  double bolt_modulus;
  double nut_modulus;
};

// VDI 2230's resilience of the bolt, term by term (m/N), with A_N = pi d^2/4 and
// A_d3 = pi d3^2/4:
//   head           delta_SK  = 0.5 d / (E_S A_N)          (hexagon head)
//   shank          sum delta_i = sum l_i / (E_S A_i)       (the unthreaded sections)
//   free_thread    delta_Gew = l_Gew / (E_S A_d3)         (loaded thread inside l_K)
//   engaged_thread delta_G   = 0.5 d / (E_S A_d3)         (the engaged thread's own stretch)
//   nut            delta_M   = 0.4 d / (E_M A_N)          (the nut's displacement, through bolt)
// A contact model that resolves the flank pair itself takes thread_pair() = delta_G + delta_M as
// the pair's compliance and puts the rest, series_with_thread_pair(), in series with it.
struct BoltResilience {
  double head;
  double shank;
  double free_thread;
  double engaged_thread;
  double nut;

  double total() const { return head + shank + free_thread + engaged_thread + nut; }
  double thread_pair() const { return engaged_thread + nut; }
  double series_with_thread_pair() const { return head + shank + free_thread; }
};

BoltResilience ThroughBoltResilience(const ThroughBolt& bolt);

// The clamped parts of a through-bolted joint: plates of one modulus E_P and total thickness l_K,
// one bearing diameter d_W under head and nut (VDI 2230 assumes equal cones), hole d_h
// and the (substitute) outside diameter D_A of the parts at the interface.
struct ClampedParts {
  double bearing_diameter;
  double hole_diameter;
  double clamp_length;
  double outer_diameter;
  double modulus;
};

// Which body VDI 2230 takes the clamped parts' deformation to be: a sleeve (D_A <= d_W), cones
// that reach D_A and continue as a sleeve (d_W < D_A < D_A,Gr), or full cones (D_A >= D_A,Gr).
enum class DeformationBody { kSleeve, kConeAndSleeve, kCone };

struct PlateResilience {
  double resilience;      // delta_P, m/N
  double cone_tangent;    // tan phi
  double limit_diameter;  // D_A,Gr = d_W + w l_K tan phi, w = 1
  DeformationBody body;
};

// VDI 2230's cone angle for a through-bolted joint:
//   tan phi_D = 0.362 + 0.032 ln(beta_L / 2) + 0.153 ln y,  beta_L = l_K / d_W, y = D_A / d_W.
double ThroughBoltConeTangent(double clamp_length, double bearing_diameter, double outer_diameter);

// delta_P of the clamped parts with VDI's cone angle (w = 1):
//   cone, D_A >= D_A,Gr:
//     delta_P = 2 ln[((d_W + d_h)(d_W + l_K tan phi - d_h)) / ((d_W - d_h)(d_W + l_K tan phi +
//     d_h))]
//               / (E_P pi d_h tan phi)
//   cone and sleeve, d_W < D_A < D_A,Gr:
//     delta_P = [ 2/(d_h tan phi) ln(((d_W + d_h)(D_A - d_h)) / ((d_W - d_h)(D_A + d_h)))
//                 + 4/(D_A^2 - d_h^2) (l_K - (D_A - d_W)/tan phi) ] / (E_P pi)
//   sleeve, D_A <= d_W:
//     delta_P = 4 l_K / (E_P pi (D_A^2 - d_h^2))
// The three agree where they meet. Requires d_h < d_W and d_h < D_A.
PlateResilience ThroughBoltPlateResilience(const ClampedParts& parts);
// The same with a given cone tangent instead of VDI's, e.g. to hold the cone fixed while D_A
// varies (VDI's tan phi grows with D_A, so its delta_P still falls slowly beyond D_A,Gr).
PlateResilience ThroughBoltPlateResilience(const ClampedParts& parts, double cone_tangent);

// Preload gained per turn of the nut past snug, P / (delta_S + delta_P), N per turn.
double PreloadPerTurn(double pitch, double bolt_resilience, double plate_resilience);

// The bolt's stress while it is tightened (VDI 2230 assembly state), A_0 = A_S for a bolt without
// a reduced shank, d_0 = (d2 + d3)/2:
//   sigma = F / A_0, tau = M_G / W_P with W_P = pi d_0^3 / 16,
//   sigma_red = sqrt(sigma^2 + 3 (k_tau tau)^2) with k_tau = 1, utilisation = sigma_red / R_p0.2.
struct AssemblyStress {
  double tensile;      // Pa
  double torsional;    // Pa
  double equivalent;   // Pa
  double utilisation;  // of the yield strength
};
AssemblyStress TighteningStress(double nominal_diameter, double pitch, double preload,
                                double thread_torque, double yield_strength);
// sigma_red = sqrt(sigma^2 + 3 tau^2) (von Mises, k_tau = 1), for the tick: no check, no throw.
inline double EquivalentStress(double tensile, double torsional) noexcept {
  return std::sqrt(tensile * tensile + 3.0 * torsional * torsional);
}

// VDI 2230's permissible assembly preload at a utilisation nu of the minimum yield strength:
//   F_M,zul = A_0 nu R_p0.2 / sqrt(1 + 3 [ (3/2)(d2/d_0)(P/(pi d2) + 1.155 mu_G) ]^2),
// the tabulated F_M,Tab for nu = 0.9. The factor 3/2 (instead of the elastic 2 that
// TighteningStress's W_P gives) takes the fully plastic torsional section modulus pi d_0^3 / 12,
// so at F_M,zul the elastic utilisation above is higher than nu.
double PermissibleAssemblyPreload(double nominal_diameter, double pitch, double yield_strength,
                                  double thread_friction, double utilisation = 0.9);

}  // namespace fitfeel::thread
