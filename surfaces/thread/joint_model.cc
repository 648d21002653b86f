#include "surfaces/thread/joint_model.h"

#include <cmath>
#include <numbers>

#include "surfaces/thread/thread_geometry.h"

namespace fitfeel::thread {

JointModel MakeJointModel(const PartSpec& bolt, const PartSpec& nut, const JointOptions& joint) {
  const HelicoidGeometry& g = HelicoidGeometryOf(bolt);
  constexpr double kPi = std::numbers::pi;
  const double d = g.diameter(), p = g.pitch();
  const double d3 = d - 1.226869 * p, d2 = d - 0.649519 * p;
  const double a_n = kPi / 4 * d * d, a_3 = kPi / 4 * d3 * d3;
  const double e_s = bolt.material.youngs_modulus, e_m = nut.material.youngs_modulus;
  JointModel model;
  model.engaged_thread_compliance = 0.5 * d / (e_s * a_3) + 0.4 * d / (e_m * a_n);
  const double ds = 0.5 * (d2 + d3);
  model.stress_area = kPi / 4 * ds * ds;
  model.polar_modulus = kPi / 16 * ds * ds * ds;
  if (!joint.present()) return model;
  const double lk = joint.clamp_length();
  const double head = 0.5 * d / (e_s * a_n);
  const double shank = joint.shank / (e_s * a_n) + (lk - joint.shank) / (e_s * a_3);
  const double dw = joint.bearing_diameter, dh = joint.hole_diameter;
  const double ep = joint.plate_modulus > 0.0 ? joint.plate_modulus : e_s;
  const double tan_phi = 0.362 + 0.032 * std::log(lk / dw / 2.0) + 0.153 * std::log(1e3);
  const double w = 1.0;
  model.plate_compliance =
      2.0 * std::log((dw + dh) * (dw + w * lk * tan_phi - dh) /
                     ((dw - dh) * (dw + w * lk * tan_phi + dh))) /
      (w * ep * kPi * dh * tan_phi);
  model.bolt_compliance = head + shank + model.engaged_thread_compliance;
  model.clamp_stiffness =
      joint.stiffness > 0.0 ? joint.stiffness : 1.0 / (head + shank + model.plate_compliance);
  const double r = 0.5 * dh, rr = 0.5 * dw;
  model.bearing_radius = 2.0 / 3.0 * (rr * rr * rr - r * r * r) / (rr * rr - r * r);
  if (joint.property_class == "8.8") model.yield_strength = d <= 16e-3 ? 640e6 : 660e6;
  if (joint.property_class == "10.9") model.yield_strength = 940e6;
  if (joint.property_class == "12.9") model.yield_strength = 1100e6;
  return model;
}

}  // namespace fitfeel::thread
