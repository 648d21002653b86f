#pragma once

#include <memory>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::thread {

// Nominal geometry of a symmetric V thread's flanks (ISO 68-1 basic profile, any flank angle):
// nominal (major) diameter d = the part's nominal size, pitch P, flank angle alpha (60 deg for
// ISO metric threads), engaged length L, and the limits of the pitch deviation and of each flank's
// half-angle deviation (paper Table 1: pitch error, thread angle error).
//
// The flanks in contact are those of the basic profile between the internal thread's minor radius
// d/2 - 5H/8 and the major radius d/2, H = P / (2 tan(alpha/2)) the fundamental triangle's
// height; the pitch radius is d/2 - 3H/8. In the mating frame y is the thread axis; a flank point
// at radius r and turn angle theta sits at x = r cos(theta), z = r sin(theta) and
//   y = P theta / (2 pi) +- (P/4 - tan(alpha/2) (r - r_pitch))   (+ flank A, - flank B).
// Each flank is a helicoid with area element sqrt((1 + k^2) r^2 + c^2) dr dtheta,
// k = tan(alpha/2), c = P / (2 pi), so its area over N = L / P turns is, in closed form,
//   A = 2 pi N [G(r)] from r1 to r2,  G(r) = r/2 sqrt(a^2 r^2 + c^2) + c^2/(2a) asinh(a r / c),
// a = sqrt(1 + k^2); the two flanks together have twice that.
class HelicoidGeometry final : public Geometry {
 public:
  HelicoidGeometry(Role role, double diameter, double pitch, double flank_angle, double length);

  Role role() const { return role_; }
  double diameter() const { return diameter_; }
  double pitch() const { return pitch_; }
  double flank_angle() const { return flank_angle_; }
  double length() const { return length_; }
  double turns() const { return length_ / pitch_; }
  double half_angle() const { return 0.5 * flank_angle_; }
  double triangle_height() const;  // H
  double inner_radius() const;     // r1 = d/2 - 5H/8
  double outer_radius() const { return 0.5 * diameter_; }
  double pitch_radius() const;  // d2 / 2 = d/2 - 3H/8
  // G(r) above: the flank area per radian of turn between radius 0 and r.
  double AreaPrimitive(double r) const;
  double flank_area() const;  // one flank, closed form

 protected:
  double DoNominalArea() const override { return 2.0 * flank_area(); }
  double DoMatingLength() const override { return length_; }
  double DoLead() const override { return pitch_; }
  std::string DoDescribe() const override;

 private:
  Role role_;
  double diameter_, pitch_, flank_angle_, length_;
};

// Parses {pitch, flank_angle, length, nominal_diameter (optional; must equal the part's nominal
// size)}; every value carries its unit. The deviation limits are the part's form (pitch_error,
// flank_angle_error); the pitch must be at least ten times pitch_error.
std::shared_ptr<const HelicoidGeometry> ParseHelicoidGeometry(const PartSpec& part,
                                                              const ConfigNode& node);

const HelicoidGeometry& HelicoidGeometryOf(const PartSpec& part);

}  // namespace fitfeel::thread
