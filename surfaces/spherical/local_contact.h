#pragma once

#include <array>
#include <limits>

#include "framework/model/gps_spec.h"

namespace fitfeel::spherical {

// A loaded plain bearing with radial clearance c = R2 - R1 touches over a small patch: a
// conformal Hertz contact of the two spheres (Johnson, Contact Mechanics, 1985, section 4.2),
// effective radius R = R1 R2 / (R2 - R1), contact modulus E* = 1 / ((1 - nu1^2)/E1 +
// (1 - nu2^2)/E2): load W = (4/3) E* sqrt(R) delta^(3/2) at the approach delta, contact radius
// a = sqrt(R delta), peak pressure p0 = 3 W / (2 pi a^2).
struct HertzContact {
  double load = 0.0;           // W, N
  double radius = 0.0;         // a, m
  double peak_pressure = 0.0;  // p0, Pa
};
HertzContact ConformalHertz(double ball_radius, double clearance, double approach,
                            double contact_modulus);
// Hertz needs a patch small against the ball; a / R1 = 0.3 is taken as the end of its validity.
inline constexpr double kHertzMaxSpread = 0.3;
// The local contact the law uses: Hertz with the gap's own curvature. Spheres of radii R1 < R2
// whose centres are e = c + delta apart have the gap (c + delta)(1 - cos phi) - delta at the angle
// phi from the load line (to first order in e / R), i.e. r^2 / (2R) - delta with R = R1 R2 / e:
// Hertz's R1 R2 / c is its limit for delta << c, 6.7 % too large at 2 um of approach on 30 um.
// While a <= 0.3 R1 it is used as it stands; beyond, R is held at the value that keeps
// a = 0.3 R1 (a load linear in delta), and once the approach exceeds the clearance (the patch
// wraps round the ball) the load is scaled by c / delta, so that it fades into the ring's bed as
// c -> 0. Non-decreasing in delta at a given clearance (delta^1.5 / sqrt(c + delta) grows),
// continuous everywhere.
HertzContact LocalContact(double ball_radius, double clearance, double approach,
                          double contact_modulus);
double ContactModulus(const Material& a, const Material& b);  // E*, Pa

// Surface compliance of an elastic layer of thickness h bonded to a rigid base and loaded normally
// (without shear) on its free face, relative to a half-space's: a normal load of wavenumber k
// displaces the face by K(kh) times what it does on a half-space (for a surface load
// p_hat(k) J0(k r), u_hat = 2 (1 - nu^2) / E * K(kh) p_hat / k),
//   K(x) = ((3 - 4 nu) sinh 2x - 2x) / ((3 - 4 nu) cosh 2x + 2 x^2 + 5 - 12 nu + 8 nu^2).
// K -> 1 for short waves (the half-space) and K -> x (1 - 2 nu) / (2 (1 - nu)^2) for long ones:
// the layer compressed without lateral strain, u = p h (1 + nu)(1 - 2 nu) / (E (1 - nu)).
// (Navier's equations for one Fourier mode with u = 0 at the base; docs/contact-mechanics.md
// section 10.)
double BondedLayerFactor(double kh, double poisson);

// One side of the loaded bearing's contact: the ring's material and its wall between the sliding
// surface and what holds it (the outer ring's outer surface in its housing, the inner ring's bore
// on its shaft), m; infinity for a solid ball (a half-space under a patch small against it).
struct ContactSide {
  Material material;
  double wall = std::numeric_limits<double>::infinity();
};

// A loaded plain bearing's local contact (the ball pushed across the clearance onto one side)
// with both rings held: the outer ring in a rigid housing, the inner ring on a rigid shaft, each
// ring's wall a layer bonded to its support (BondedLayerFactor) of its thickness at the
// equator. Conformal Hertz (Johnson 4.2) takes both sides as half-spaces, which the walls of a
// spherical plain bearing are not: GE 20 E's are 3 and 4.5 mm thick under patches 6.5 to 11 mm
// across, and CalculiX carries 2.1 to 3.1 times Hertz's load (tools/fem/data/bearing.csv); this
// model is within 3.7 to 7.8 % of it.
//
// The contact is axisymmetric about the load line, its gap LocalContact's r^2 / (2 R) - delta, the
// pressure piecewise constant on rings of the patch (Boussinesq's annulus displacement by
// elliptic integrals plus each wall's correction by a Hankel integral of (K - 1)), solved with
// non-negative pressure. By dimensional analysis the load is Hertz's times a function of
// s = R delta / h^2 alone (the walls' ratio, the materials fixed), as are the patch radius and the
// peak pressure: tabulated in s once, read by interpolation (allocation-free, for the tick). The
// three ratios are taken against the same numerics run with half-spaces, which removes the rings'
// discretisation error from them (a half-space gives exactly Hertz).
class LayeredConformalContact {
 public:
  LayeredConformalContact() = default;
  // Throws UserError on a non-positive radius, modulus or wall.
  LayeredConformalContact(double ball_radius, const ContactSide& ball, const ContactSide& ring);

  // The local contact at the clearance c and the approach delta: LocalContact's (conformal Hertz
  // with R held to keep a <= 0.3 R1, faded by c / delta once the patch wraps round the ball) with
  // the walls' ratios at s = R delta / h^2.
  HertzContact Load(double clearance, double approach) const noexcept;

  // load / Hertz load, patch radius / Hertz radius, peak pressure / Hertz peak at s.
  struct Ratios {
    double load = 1.0, radius = 1.0, peak_pressure = 1.0;
  };
  Ratios RatiosAt(double s) const noexcept;

  // Table points over log s, from kSpan below the largest s the cap a <= 0.3 R1 allows (or kBed)
  // to that. Beyond s = kBed (a = 10 h) the walls are a bed (p = M delta / h): the load and peak
  // pressure ratios carry on as sqrt(s), the bed's scaling against Hertz, the radius ratio stays.
  static constexpr int kPoints = 25;
  static constexpr double kSpan = 1e4;
  static constexpr double kBed = 100.0;
  // Rings of the patch in each solve.
  static constexpr int kRings = 40;

 private:
  double ball_radius_ = 0.0;
  double contact_modulus_ = 0.0;
  double wall_ = std::numeric_limits<double>::infinity();  // h, the thinner wall
  double log_lowest_ = 0.0, log_step_ = 1.0;
  std::array<Ratios, kPoints> table_{};
};

}  // namespace fitfeel::spherical
