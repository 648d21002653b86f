#include "surfaces/thread/thread_torque.h"

#include <cmath>
#include <numbers>

#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/bolting_arguments.h"

namespace fitfeel::thread {
namespace {

// The flank angles HelicoidGeometry accepts: no standard V or trapezoidal thread lies outside.
void CheckFlankAngle(const char* function, double flank_angle) {
  RequireWithin(function, "flank_angle", flank_angle, std::numbers::pi / 9.0,
                2.0 * std::numbers::pi / 3.0, Dimension::kAngle);
}

void CheckFriction(const char* function, const char* argument, double friction) {
  RequireWithin(function, argument, friction, 0.0, 1.0, Dimension::kDimensionless);
}

// The radius or diameter the ratio is taken at, the pitch and the friction coefficient.
void CheckScrew(const char* function, const char* size_name, double size, double pitch,
                double friction) {
  RequirePositive(function, size_name, size, Dimension::kLength);
  RequirePositive(function, "pitch", pitch, Dimension::kLength);
  CheckFriction(function, "friction", friction);
}

TorqueRatio Split(double total, double pitch) {
  const double lead = pitch / (2.0 * std::numbers::pi);
  return {total, lead, total - lead};
}

void CheckAnnulus(const char* function, double bearing_diameter, double hole_diameter,
                  double friction) {
  RequirePositive(function, "bearing_diameter", bearing_diameter, Dimension::kLength);
  RequirePositive(function, "hole_diameter", hole_diameter, Dimension::kLength);
  RequireLess(function, "hole_diameter", hole_diameter, "bearing_diameter", bearing_diameter,
              Dimension::kLength);
  CheckFriction(function, "friction", friction);
}

}  // namespace

TorqueRatio VdiThreadTorqueRatio(double pitch_diameter, double pitch, double flank_angle,
                                 double friction) {
  constexpr const char* kFunction = "VdiThreadTorqueRatio";
  CheckScrew(kFunction, "pitch_diameter", pitch_diameter, pitch, friction);
  CheckFlankAngle(kFunction, flank_angle);
  const double phi = std::atan(pitch / (std::numbers::pi * pitch_diameter));
  const double rho = std::atan(friction / std::cos(0.5 * flank_angle));
  return Split(0.5 * pitch_diameter * std::tan(phi + rho), pitch);
}

TorqueRatio VdiThreadTorqueRatioApproximate(double pitch_diameter, double pitch, double friction) {
  constexpr const char* kFunction = "VdiThreadTorqueRatioApproximate";
  CheckScrew(kFunction, "pitch_diameter", pitch_diameter, pitch, friction);
  const double lead = 0.16 * pitch;
  const double total = lead + 0.58 * pitch_diameter * friction;
  return {total, lead, total - lead};
}

TorqueRatio SingleRadiusTorqueRatio(double radius, double pitch, double flank_angle,
                                    double friction) {
  constexpr const char* kFunction = "SingleRadiusTorqueRatio";
  CheckScrew(kFunction, "radius", radius, pitch, friction);
  CheckFlankAngle(kFunction, flank_angle);
  const double tan_lead = pitch / (2.0 * std::numbers::pi * radius);
  const double cos_lead = 1.0 / std::sqrt(1.0 + tan_lead * tan_lead);
  const double normal_half_angle = std::atan(std::tan(0.5 * flank_angle) * cos_lead);
  const double mu = friction / std::cos(normal_half_angle);
  return Split(radius * (tan_lead + mu) / (1.0 - mu * tan_lead), pitch);
}

TorqueRatio HelicoidTorqueRatio(double pitch, double flank_angle, double inner_radius,
                                double outer_radius, double friction, FlankPressure pressure,
                                int points) {
  constexpr const char* kFunction = "HelicoidTorqueRatio";
  RequirePositive(kFunction, "pitch", pitch, Dimension::kLength);
  CheckFlankAngle(kFunction, flank_angle);
  RequirePositive(kFunction, "inner_radius", inner_radius, Dimension::kLength);
  RequirePositive(kFunction, "outer_radius", outer_radius, Dimension::kLength);
  RequireLess(kFunction, "inner_radius", inner_radius, "outer_radius", outer_radius,
              Dimension::kLength);
  CheckFriction(kFunction, "friction", friction);
  const double k = std::tan(0.5 * flank_angle);
  const double c = pitch / (2.0 * std::numbers::pi);
  const QuadratureRule rule = GaussLegendreRule(points);
  const double half = 0.5 * (outer_radius - inner_radius);
  const double mid = 0.5 * (outer_radius + inner_radius);
  // In the cylindrical frame (e_r, e_theta, y) of the flank point (r, theta): the unit normal out
  // of the bolt n = (k, -c/r, 1) / N with N = J / r, the unit helix tangent (the sliding
  // direction of a screw motion) t = (0, r, c) / S, and the area element J dr dtheta,
  // J = sqrt((1 + k^2) r^2 + c^2), S = sqrt(r^2 + c^2). On the nut the flank pushes p n and
  // friction pulls -mu p t, so per unit turned angle
  //   F = int p (n_y - mu t_y) J dr,   T = -int p r (n_theta - mu t_theta) J dr.
  double force = 0.0, torque = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double r = mid + half * rule.nodes[i];
    const double w = half * rule.weights[i];
    const double j = std::sqrt((1.0 + k * k) * r * r + c * c);
    const double n = j / r;
    const double s = std::sqrt(r * r + c * c);
    const double p = pressure == FlankPressure::kWinkler ? 1.0 / n : 1.0;
    force += w * p * (1.0 / n - friction * c / s) * j;
    torque += w * p * (c / n + friction * r * r / s) * j;
  }
  return Split(torque / force, pitch);
}

double VdiBearingTorqueRatio(double bearing_diameter, double hole_diameter, double friction) {
  CheckAnnulus("VdiBearingTorqueRatio", bearing_diameter, hole_diameter, friction);
  return friction * 0.25 * (bearing_diameter + hole_diameter);
}

double UniformAnnulusTorqueRatio(double bearing_diameter, double hole_diameter, double friction) {
  CheckAnnulus("UniformAnnulusTorqueRatio", bearing_diameter, hole_diameter, friction);
  const double big = 0.5 * bearing_diameter, small = 0.5 * hole_diameter;
  return friction * 2.0 / 3.0 * (big * big * big - small * small * small) /
         (big * big - small * small);
}

double VdiTighteningTorque(double nominal_diameter, double pitch, double preload,
                           double thread_friction, double bearing_diameter, double hole_diameter,
                           double bearing_friction) {
  constexpr const char* kFunction = "VdiTighteningTorque";
  RequireNonNegative(kFunction, "preload", preload, Dimension::kForce);
  CheckFriction(kFunction, "thread_friction", thread_friction);
  const double d2 = PitchDiameter(nominal_diameter, pitch);
  return preload * (VdiThreadTorqueRatioApproximate(d2, pitch, thread_friction).total +
                    VdiBearingTorqueRatio(bearing_diameter, hole_diameter, bearing_friction));
}

QuadratureRule GaussLegendreRule(int points) {
  RequireWithin("GaussLegendreRule", "points", points, 1, 200, Dimension::kDimensionless);
  const int n = points;
  QuadratureRule rule{std::vector<double>(n), std::vector<double>(n)};
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Newton on P_n from the Tricomi estimate of the i-th root; the roots are symmetric.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int m = 2; m <= n; ++m) {
        const double p2 = ((2.0 * m - 1.0) * x * p1 - (m - 1.0) * p0) / m;
        p0 = p1;
        p1 = p2;
      }
      // P_n' = n (x P_n - P_{n-1}) / (x^2 - 1)
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    rule.nodes[i] = -x;
    rule.nodes[n - 1 - i] = x;
    rule.weights[i] = weight;
    rule.weights[n - 1 - i] = weight;
  }
  return rule;
}

}  // namespace fitfeel::thread
