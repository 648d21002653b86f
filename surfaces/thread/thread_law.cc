#include "surfaces/thread/thread_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "framework/core/error.h"
#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/joint_model.h"
#include "surfaces/thread/thread_geometry.h"

namespace fitfeel::thread {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;  // rad

// Per turn of one flank, the integral of n_y^2 dA: what a unit axial shift of a rigid nut
// presses into the flank, m^2. The area element is r N dr dtheta and n_y = 1 / N, N(r)^2 =
// 1 + k^2 + c^2 / r^2 (docs/threads.md), so it is 2 pi times the integral of r / N over the band.
double AxialAreaPerTurn(const HelicoidGeometry& g) {
  const double k = std::tan(g.half_angle()), c = g.pitch() / kTurn;
  const double r1 = g.inner_radius(), r2 = g.outer_radius();
  constexpr int kPoints = 256;
  double sum = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double r = r1 + (i + 0.5) * (r2 - r1) / kPoints;
    sum += r / std::sqrt(1.0 + k * k + c * c / (r * r));
  }
  return kTurn * sum * (r2 - r1) / kPoints;
}

}  // namespace

void ThreadLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                          const ModelSettings& settings) {
  const HelicoidGeometry& bolt = HelicoidGeometryOf(inner);
  const HelicoidGeometry& nut = HelicoidGeometryOf(outer);
  const ThreadOptions options = ThreadOptionsOf(settings);
  const JointModel joint = MakeJointModel(inner, outer, options.joint);
  flank_stiffness_ = settings.contact_stiffness > 0.0 ? settings.contact_stiffness
                                                      : 1.0 / joint.engaged_thread_compliance;
  // The analyzer's countersink ramps take half a turn at each face of the nut.
  const double effective_turns = std::max(nut.turns() - 1.0, 0.25);
  pressure_ = flank_stiffness_ / (effective_turns * AxialAreaPerTurn(bolt));
  flank_friction_ = settings.friction;
  flank_junctions_ = StickSlipFriction(FrictionOf(settings));
  lead_per_radian_ = bolt.pitch() / kTurn;
  pitch_radius_ = bolt.pitch_radius();
  helix_radius_ = std::hypot(pitch_radius_, lead_per_radian_);
  if (options.joint.present()) {
    clamp_stiffness_ = joint.clamp_stiffness;
    face_friction_ = options.joint.bearing_friction;
    FrictionParameters face = FrictionOf(settings);
    face.kinetic_coefficient = face.static_coefficient = face_friction_;
    face_junctions_ = StickSlipFriction(face);
    bearing_radius_ = joint.bearing_radius;
  }
  stress_area_ = joint.stress_area;
  polar_modulus_ = joint.polar_modulus;
  yield_ = joint.yield_strength;
}

void ThreadLaw::Compose(const ContactState& contact, double flank_slip, double face_slip,
                        Wrench* out) const noexcept {
  const double friction = flank_friction_ * flank_slip;
  out->force = -pressure_ * (contact.normal_sum + friction * contact.slide_sum);
  out->torque = -pressure_ * (contact.normal_moment + friction * contact.slide_moment);
  if (contact.stop_closure > 0.0) {
    const double load = clamp_stiffness_ * contact.stop_closure;
    out->force.y() -= load;
    out->torque.y() -= face_friction_ * face_slip * load * bearing_radius_;
  }
}

void ThreadLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                           Wrench* out) const noexcept {
  // The slip speed along the helix at the pitch radius, and the face's at its friction radius.
  const double helix = (motion.angular_velocity.y() * pitch_radius_ * pitch_radius_ +
                        motion.velocity.y() * lead_per_radian_) /
                       helix_radius_;
  const double face = motion.angular_velocity.y() * bearing_radius_;
  Compose(contact, std::tanh(helix / kFrictionSmoothingVelocity),
          std::tanh(face / kFrictionSmoothingVelocity), out);
}

void ThreadLaw::DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                                    LawState* state, Wrench* out) const noexcept {
  // Slip positions: a cell's displacement along the helix at the pitch radius, and the face's
  // arc at its friction radius; the junctions' force over their sliding level is the share of
  // friction each contact carries.
  const double helix =
      (motion.angle * pitch_radius_ * pitch_radius_ + motion.depth * lead_per_radian_) /
      helix_radius_;
  const double flank_normal = pressure_ * contact.interference_volume;
  double flank_slip = 0.0, face_slip = 0.0;
  const Eigen::Vector2d flank =
      flank_junctions_.Step(Eigen::Vector2d(helix, 0.0), flank_normal, &state->friction);
  if (flank_normal > 0.0 && flank_friction_ > 0.0) {
    flank_slip = -flank.x() / (flank_friction_ * flank_normal);
  }
  const double face_normal = clamp_stiffness_ * contact.stop_closure;
  const Eigen::Vector2d face = face_junctions_.Step(
      Eigen::Vector2d(motion.angle * bearing_radius_, 0.0), face_normal, &state->stop_friction);
  if (face_normal > 0.0 && face_friction_ > 0.0) {
    face_slip = -face.x() / (face_friction_ * face_normal);
  }
  Compose(contact, flank_slip, face_slip, out);
}

bool ThreadLaw::DoRadialJacobian(const ContactState& contact,
                                 Eigen::Matrix2d* jacobian) const noexcept {
  if (!contact.interference || !contact.resultant_jacobian.allFinite()) return false;
  *jacobian = -pressure_ * contact.resultant_jacobian;
  return true;
}

ElasticLimitCheck ThreadLaw::DoCheckElasticLimit(const ContactState& contact) const noexcept {
  ElasticLimitCheck check;
  if (!(yield_ > 0.0) || !contact.interference) return check;
  // The bolt carries the flanks' axial load in tension and their torque in torsion (k_tau = 1
  // while it is being turned; the friction taken as sliding).
  const double tension =
      pressure_ * std::abs(contact.normal_sum.y() + flank_friction_ * contact.slide_sum.y());
  const double torsion =
      pressure_ * std::abs(contact.normal_moment.y() + flank_friction_ * contact.slide_moment.y());
  check.utilisation = EquivalentStress(tension / stress_area_, torsion / polar_modulus_) / yield_;
  check.part = 2;
  return check;
}

}  // namespace fitfeel::thread
