#pragma once

#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"
#include "surfaces/spherical/local_contact.h"

namespace fitfeel::spherical {

// Contact pressure per unit radial interference of a solid ball of radius a in a thick spherical
// shell of outer radius b (Lame's solution for spheres, docs/oracles.md), Pa/m:
//   p / delta = 1 / ( a [ (1 - 2 nu1)/E1 + ((1 - 2 nu2) a^3 + (1 + nu2) b^3 / 2) / (E2 (b^3 - a^3))
//   ] )
// The inner ring of a real bearing has a cylindrical bore; it is taken as a solid ball (its bore
// stiffens nothing the spherical solution could describe, and the ring is much stiffer than the
// outer ring's shell, which dominates the compliance).
double ThickShellPressurePerInterference(double a, double b, const Material& ball,
                                         const Material& shell);

// One plane slice of a spherical plain bearing: a disc of diameter dk (with a bore ball_bore,
// 0 for a solid ball) in a ring of bore dk and outer diameter D, Lame's thick-walled cylinders in
// plane stress, Pa/m of radial interference in the slice's plane:
//   P = (2 / dk) / ( ((dk^2 + d^2)/(dk^2 - d^2) - nu1)/E1 + ((D^2 + dk^2)/(D^2 - dk^2) + nu2)/E2 )
// (the ball's term is 1 - nu1 for d = 0). For GE 20 E's equator (dk 29 mm, D 35 mm, steel, solid)
// 2.27 MPa/um, 2.62 times softer than the thick shell of radii 14.5 and 17.5 mm (5.95 MPa/um),
// which assumes material all round the ball.
double RingPressurePerInterference(double dk, double outer_diameter, const Material& ball,
                                   const Material& ring, double ball_bore = 0.0);

// The outer ring of width C around the ball's band, cut into plane slices normal to the bearing
// axis (docs/contact-mechanics.md, section 8). The slice at height y has radius r = sqrt(a^2 - y^2)
// from the axis, so its wall is thicker towards the band's edges; a normal interference delta
// of the spheres is a radial interference delta a / r in the slice's plane, and the slice's
// radial traction is the sphere's normal pressure. A uniform interference thus gives the bursting
// force 2 pi a delta * integral of P_slice(2 r(y)) dy over the band; the coefficient returned,
//   P_band = a * integral P_slice(2 r(y)) dy / integral r(y) dy,
// gives the same when every socket cell carries P_band * delta (the radial stiffness under an
// offset and the normal force differ from the slices' by under 1 % for GE 20 E). GE 20 E: 2.72
// MPa/um with a solid ball, 1.98 with the inner ring's 20 mm bore; CalculiX (axisymmetric, the
// ball's 16 mm band in the ring's 12 mm) 2.81 and 2.15: the slices leave out the ball's wider band
// and the ring's axial continuity, 3 and 8 % (tools/fem/data/axisymmetric.csv, tested).
double BandPressurePerInterference(double dk, double band_width, double outer_diameter,
                                   double ball_bore, const Material& ball, const Material& ring);

// Knuckle (spherical plain) bearing. Two contact regimes, each carried by the closed form that
// holds there:
//  - interference all round (ball larger than the socket) or a contact wrapped round the ball:
//    each socket cell's pressure is p = P_ring * delta (P_ring the band's coefficient above), so
//    sum p ds = P_ring * interference_volume and the radial force is -P_ring * sum(delta ds n);
//  - the ball pushed across the clearance onto one side (a loaded plain bearing): the local
//    load W of the approach delta = the largest interference (LayeredConformalContact:
//    conformal Hertz with the rings' walls as layers bonded to a rigid housing and shaft), with
//    the clearance there c = e - delta (e the centre's offset), along minus the resultant's
//    direction; normal force W. A local patch is carried by the material under it, not by the
//    ring's breathing: the local load is stiffer than the per-cell bed there (GE 20 E at 1 um of
//    approach and 61 um of clearance: 492 N against about 84 N).
// The larger of the two loads is taken: both grow with the offset, so the support stays monotone
// (the settling search needs that) and continuous; as c -> 0 the local load fades (LocalContact)
// and the bed remains.
// Friction torque about the bearing axis: stick-slip on the arc angle * rho with the run's state
// (framework/model/friction.h; without state the smoothed kinetic law), rho the band's mean
// distance from the axis, (1/B) * integral of sqrt(a^2 - y^2) dy: for a uniform pressure exactly
// mu * integral of p * (distance from the axis) ds (a cell's arm is a cos(latitude), not a, so
// mu * sum p ds * a would overstate the torque by 3 % for GE 20 E's outer ring).
// Elastic limit: per cell P_ring * delta against the ring's bore (DIN 7190 hub form with
// Q = dk / D) and the ball's (a hollow shaft with the inner ring's bore); the local contact's
// peak pressure against Hertz's 1.61 R_e (elastic_limit.h).
// Tilting (omega_x, omega_z) and the axial force are not modelled: the bearing's mating motion is
// the rotation about its axis, and the ball is captive along it.
class KnuckleBearingLaw final : public ResistanceLaw {
 public:
  double pressure_per_interference() const { return pressure_per_interference_; }
  double friction_arm() const { return arm_; }

 protected:
  // The ring coefficient every socket cell's pressure uses under all-round interference.
  double DoPressurePerInterference() const override { return pressure_per_interference_; }
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;
  void DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion, LawState* state,
                           Wrench* out) const noexcept override;
  ElasticLimitCheck DoCheckElasticLimit(const ContactState& contact) const noexcept override;
  // The ring's bed: -P times the pressure resultant; none where the local contact carries the
  // load (Normal).
  bool DoRadialJacobian(const ContactState& contact,
                        Eigen::Matrix2d* jacobian) const noexcept override;

 private:
  // Radial force into `out`; returns the normal force and, when the local contact carries the
  // load, it in `hertz` (load 0 otherwise).
  double Normal(const ContactState& contact, Wrench* out, HertzContact* hertz) const noexcept;

  StickSlipFriction friction_;
  double radius_ = 0.0;
  LayeredConformalContact local_;
  double ring_yield_pressure_ = 0.0;  // 0: no yield strength given
  double ball_yield_pressure_ = 0.0;
  double hertz_yield_pressure_ = 0.0;
  int hertz_yield_part_ = 1;  // the part of the lower yield strength (ElasticLimitCheck::part)
  double arm_ = 0.0;
  double pressure_per_interference_ = 0.0;
};

}  // namespace fitfeel::spherical
