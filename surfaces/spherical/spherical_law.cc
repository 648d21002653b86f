#include "surfaces/spherical/spherical_law.h"

#include <cmath>

#include <algorithm>
#include <limits>
#include <numbers>

#include "framework/core/error.h"
#include "framework/model/elastic_limit.h"
#include "surfaces/spherical/gauss_legendre.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {

double ThickShellPressurePerInterference(double a, double b, const Material& ball,
                                         const Material& shell) {
  if (!(a > 0.0) || !(b > a)) throw UserError("thick-shell pressure needs 0 < a < b");
  if (!(ball.youngs_modulus > 0.0) || !(shell.youngs_modulus > 0.0)) {
    throw UserError("thick-shell pressure needs positive Young's moduli");
  }
  const double a3 = a * a * a, b3 = b * b * b;
  const double ball_term = (1.0 - 2.0 * ball.poisson) / ball.youngs_modulus;
  const double shell_term = ((1.0 - 2.0 * shell.poisson) * a3 + (1.0 + shell.poisson) * b3 / 2.0) /
                            (shell.youngs_modulus * (b3 - a3));
  return 1.0 / (a * (ball_term + shell_term));
}

double RingPressurePerInterference(double dk, double outer_diameter, const Material& ball,
                                   const Material& ring, double ball_bore) {
  if (!(dk > 0.0) || !(outer_diameter > dk)) throw UserError("ring pressure needs 0 < dk < D");
  if (!(ball_bore >= 0.0) || !(ball_bore < dk)) throw UserError("ring pressure needs 0 <= d < dk");
  if (!(ball.youngs_modulus > 0.0) || !(ring.youngs_modulus > 0.0)) {
    throw UserError("ring pressure needs positive Young's moduli");
  }
  const double d2 = outer_diameter * outer_diameter, d1 = dk * dk, di = ball_bore * ball_bore;
  const double ring_term = ((d2 + d1) / (d2 - d1) + ring.poisson) / ring.youngs_modulus;
  const double ball_term = ((d1 + di) / (d1 - di) - ball.poisson) / ball.youngs_modulus;
  return (2.0 / dk) / (ball_term + ring_term);
}

double BandPressurePerInterference(double dk, double band_width, double outer_diameter,
                                   double ball_bore, const Material& ball, const Material& ring) {
  const double a = 0.5 * dk, h = 0.5 * band_width;
  if (!(h > 0.0) || !(h < a)) throw UserError("band pressure needs 0 < width < dk");
  if (!(ball_bore < 2.0 * std::sqrt(a * a - h * h))) {
    throw UserError("band pressure needs the ball's bore inside the band's edge");
  }
  // Composite 4-point Gauss-Legendre over the band; the integrands are smooth (r >= its value at
  // the band's edge), so 32 panels reach double precision.
  constexpr int kPanels = 32;
  const double panel = band_width / kPanels;
  double pressure = 0.0, radius = 0.0;
  for (int k = 0; k < kPanels; ++k) {
    const double centre = -h + (k + 0.5) * panel;
    for (int g = 0; g < 4; ++g) {
      const double y = centre + 0.5 * panel * kGaussNodes4[g];
      const double r = std::sqrt(a * a - y * y);
      pressure += kGaussWeights4[g] *
                  RingPressurePerInterference(2.0 * r, outer_diameter, ball, ring, ball_bore);
      radius += kGaussWeights4[g] * r;
    }
  }
  return a * pressure / radius;
}

void KnuckleBearingLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                                  const ModelSettings& settings) {
  const SphericalGeometry& ball = GeometryOf(inner);
  const SphericalGeometry& socket = GeometryOf(outer);
  friction_ = StickSlipFriction(FrictionOf(settings));
  arm_ = socket.mean_axis_distance();
  radius_ = socket.radius();
  const double dk = 2.0 * socket.radius();
  pressure_per_interference_ =
      BandPressurePerInterference(dk, socket.width(), socket.outer_diameter(), ball.bore_diameter(),
                                  inner.material, outer.material);
  // The walls at the equator: the outer ring's to its housing, the inner ring's to its shaft.
  const double ball_wall = ball.bore_diameter() > 0.0 ? ball.radius() - 0.5 * ball.bore_diameter()
                                                      : std::numeric_limits<double>::infinity();
  local_ = LayeredConformalContact(radius_, {inner.material, ball_wall},
                                   {outer.material, 0.5 * socket.outer_diameter() - radius_});
  const double ring_re = outer.material.yield_strength, ball_re = inner.material.yield_strength;
  ring_yield_pressure_ =
      ring_re > 0.0 ? HubYieldPressure(dk, socket.outer_diameter(), ring_re) : 0.0;
  ball_yield_pressure_ =
      ball_re > 0.0 ? ShaftYieldPressure(dk, ball.bore_diameter(), ball_re) : 0.0;
  const double weaker =
      ring_re > 0.0 && ball_re > 0.0 ? std::min(ring_re, ball_re) : std::max(ring_re, ball_re);
  hertz_yield_pressure_ = weaker > 0.0 ? HertzYieldPeakPressure(weaker) : 0.0;
  hertz_yield_part_ = weaker == ring_re ? 1 : 2;
}

double KnuckleBearingLaw::Normal(const ContactState& contact, Wrench* out,
                                 HertzContact* hertz) const noexcept {
  out->SetZero();
  *hertz = HertzContact{};
  if (!(contact.interference_volume > 0.0)) return 0.0;
  const Eigen::Vector2d bed = -pressure_per_interference_ * contact.pressure_resultant;
  const double bed_load = bed.norm();
  const double clearance = contact.offset_distance - contact.max_interference;
  const HertzContact local = local_.Load(clearance, contact.max_interference);
  if (local.load > bed_load && bed_load > 0.0) {
    *hertz = local;
    const Eigen::Vector2d f = (local.load / bed_load) * bed;
    out->force.x() = f.x();
    out->force.z() = f.y();
    return local.load;
  }
  out->force.x() = bed.x();
  out->force.z() = bed.y();
  return pressure_per_interference_ * contact.interference_volume;
}

bool KnuckleBearingLaw::DoRadialJacobian(const ContactState& contact,
                                         Eigen::Matrix2d* jacobian) const noexcept {
  Wrench force;
  HertzContact hertz;
  Normal(contact, &force, &hertz);
  if (hertz.load > 0.0 || !(contact.interference_volume > 0.0)) return false;
  *jacobian = -pressure_per_interference_ * contact.resultant_jacobian;
  return true;
}

void KnuckleBearingLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                                   Wrench* out) const noexcept {
  HertzContact hertz;
  const double normal = Normal(contact, out, &hertz);
  out->torque.y() =
      friction_.Smoothed({motion.angular_velocity.y() * arm_, 0.0}, normal).x() * arm_;
}

void KnuckleBearingLaw::DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                                            LawState* state, Wrench* out) const noexcept {
  HertzContact hertz;
  const double normal = Normal(contact, out, &hertz);
  out->torque.y() = friction_.Step({motion.angle * arm_, 0.0}, normal, &state->friction).x() * arm_;
}

ElasticLimitCheck KnuckleBearingLaw::DoCheckElasticLimit(
    const ContactState& contact) const noexcept {
  ElasticLimitCheck check;
  Wrench unused;
  HertzContact hertz;
  if (!(Normal(contact, &unused, &hertz) > 0.0)) return check;
  if (hertz.load > 0.0) {
    if (hertz_yield_pressure_ > 0.0) {
      check.utilisation = hertz.peak_pressure / hertz_yield_pressure_;
      check.part = hertz_yield_part_;
    }
    return check;
  }
  const double peak = pressure_per_interference_ * contact.max_interference;
  if (ring_yield_pressure_ > 0.0) {
    check.utilisation = peak / ring_yield_pressure_;
    check.part = 1;
  }
  if (ball_yield_pressure_ > 0.0 && peak / ball_yield_pressure_ > check.utilisation) {
    check.utilisation = peak / ball_yield_pressure_;
    check.part = 2;
  }
  return check;
}

}  // namespace fitfeel::spherical
