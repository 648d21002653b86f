#include "framework/runtime/joint_stage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include <Eigen/LU>

#include "framework/core/error.h"
#include "framework/runtime/contact_search.h"

namespace fitfeel {

// The summed wrench on the moving body about its reference axis (scene frame), as a balance reads
// it.
struct JointStage::Sum {
  Wrench wrench;
  int evaluations = 0;
  bool engaged = false;  // some feature's surfaces overlap axially
};

namespace {

// The balance's proximal stiffness k_r, N/m (and N per metre of lever arc): it only regularises
// the coordinates nothing else holds (a body in clearance under its load, a free twist) and
// vanishes once the body rests. 10 N/um: a 6 N load then moves a body in clearance by 0.6 um an
// iteration, up to 4.8 um a tick, across a fit's clearance in a few ticks; and it stays three to
// four orders below the stiff contacts (N/nm) that the Newton steps resolve, keeping their
// Jacobian well conditioned.
constexpr double kProximalStiffness = 1e7;
// The longest step of one Newton iteration, m: above the radial clearance of the fits the joint
// holds, so that a body in clearance reaches its wall within an iteration or two, and short
// enough that a step never leaves the tables' range.
constexpr double kMaxStep = 50e-6;
// Finite-difference step of the Jacobian, m: exact for the laws' piecewise-linear springs away
// from a kink, and far above the rounding of an offset of millimetres.
constexpr double kDifferenceStep = 1e-9;
// A balance is reached where the residual force is below this fraction of the forces at play
// (the contacts', the load's and the torque's at the lever), plus this much of a newton.
constexpr double kForceTolerance = 1e-6;
// Regula falsi steps of one line search at most.
constexpr int kLineSearchSteps = 6;

struct JointState final : StageState {
  Eigen::Vector3d q{0.0, 0.0, 0.0};  // offset (x, z), lever * twist
  // The last finite-difference Jacobian of the balance, reused while its steps make progress
  // (the contacts' stiffness changes only where one starts or ends).
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Identity();
  bool jacobian_valid = false;
  std::array<LawState, kMaxJointFeatures> law;
};

// The (x, z) rotation by an angle about +y, given its cosine c and sine s: (x, z) -> (x c + z s,
// -x s + z c). The features' angles are turned into c and s once, by the constructor, and the
// twist once per evaluation of the balance: taken at every turn they cost a sixth of the tick.
Eigen::Vector2d Turn(const Eigen::Vector2d& v, double c, double s) {
  return {c * v.x() + s * v.y(), -s * v.x() + c * v.y()};
}

}  // namespace

JointStage::JointStage(std::vector<JointFeature> features, const Options& options)
    : features_(std::move(features)), options_(options) {
  if (features_.empty() || features_.size() > static_cast<std::size_t>(kMaxJointFeatures)) {
    throw UserError("joint stage: 1 to " + std::to_string(kMaxJointFeatures) +
                    " features, not " + std::to_string(features_.size()));
  }
  double lever = 0.0;
  for (const JointFeature& f : features_) {
    if (f.analyzer == nullptr || f.law == nullptr || !f.analyzer->prepared()) {
      throw UserError("joint stage: every feature needs a prepared analyzer and law");
    }
    lever = std::max({lever, f.moving_axis.norm(), f.fixed_axis.norm()});
  }
  for (std::size_t i = 0; i < features_.size(); ++i) {
    feature_cos_[i] = std::cos(features_[i].angle);
    feature_sin_[i] = std::sin(features_[i].angle);
  }
  if (lever > 0.0) lever_ = lever;
  if (!std::isfinite(options.depth_origin) || !(options.proxy_stiffness > 0.0)) {
    throw UserError("joint stage: the depth origin must be finite and the proxy stiffness > 0");
  }
}

std::unique_ptr<StageState> JointStage::DoMakeState() const {
  return std::make_unique<JointState>();
}

void JointStage::Evaluate(const Eigen::Vector3d& q, double depth, const PartState& part,
                          LawState* states, Sum* sum, StageOutput* out) const noexcept {
  sum->wrench.SetZero();
  sum->engaged = false;
  const double twist = q.z() / lever_;
  const double twist_c = std::cos(twist), twist_s = std::sin(twist);
  const Eigen::Vector2d offset = q.head<2>();
  const Eigen::Vector3d reflect(1.0, 1.0, -1.0);
  for (std::size_t i = 0; i < features_.size(); ++i) {
    const JointFeature& f = features_[i];
    const double c = feature_cos_[i], s = feature_sin_[i];
    // Where the feature's moving axis is, from the body's reference axis, and its pose in the
    // feature's own frame (the joint frame turned by f.angle).
    const Eigen::Vector2d arm = Turn(f.moving_axis, twist_c, twist_s);
    MatingPose pose;
    pose.depth = depth - f.engages_after;
    pose.offset = Turn(offset + arm - f.fixed_axis, c, -s);
    pose.angle = twist;
    const bool outer = f.moving == Role::kOuter;
    ContactState contact;
    f.analyzer->Evaluate(AnalyzerPose(pose, f.moving), &contact);
    ++sum->evaluations;
    sum->engaged = sum->engaged || contact.engaged;
    MatingMotion motion;
    const Eigen::Vector2d v = Turn(Eigen::Vector2d(part.velocity.x(), part.velocity.z()), c, -s);
    motion.velocity = Eigen::Vector3d(v.x(), part.velocity.y(), v.y());
    motion.angular_velocity = part.angular_velocity;
    if (outer) {
      motion.velocity = motion.velocity.cwiseProduct(reflect);
      motion.angular_velocity = motion.angular_velocity.cwiseProduct(reflect);
    }
    motion.depth = pose.depth;
    motion.angle = pose.angle;
    Wrench w;
    if (states == nullptr) {
      f.law->Evaluate(contact, motion, &w);
    } else {
      // Out of engagement the junctions let go, so a re-entry forms its contact afresh.
      if (!contact.engaged) states[i] = LawState{};
      f.law->Evaluate(contact, motion, &states[i], &w);
    }
    if (outer) {
      w.force = w.force.cwiseProduct(reflect);
      w.torque = w.torque.cwiseProduct(reflect);
    }
    // Back into the joint frame, and about the body's reference axis.
    const Eigen::Vector2d fxz = Turn(Eigen::Vector2d(w.force.x(), w.force.z()), c, s);
    const Eigen::Vector2d txz = Turn(Eigen::Vector2d(w.torque.x(), w.torque.z()), c, s);
    const Eigen::Vector3d force(fxz.x(), w.force.y(), fxz.y());
    const Eigen::Vector3d lever_arm(arm.x(), 0.0, arm.y());
    sum->wrench.force += force;
    sum->wrench.torque += Eigen::Vector3d(txz.x(), w.torque.y(), txz.y()) + lever_arm.cross(force);
    if (out != nullptr) {
      out->feature_axial[i] = force.y();
      const ElasticLimitCheck elastic = f.law->CheckElasticLimit(contact);
      if (elastic.utilisation > out->elastic.utilisation) out->elastic = elastic;
      if (i == 0) {
        out->contact = contact;
        SceneContact(&out->contact, f.moving);
      } else {
        out->contact.engaged = out->contact.engaged || contact.engaged;
        out->contact.interference = out->contact.interference || contact.interference;
      }
    }
  }
}

void JointStage::DoEvaluate(const PartState& part, StageState* state,
                            StageOutput* out) const noexcept {
  auto* run = static_cast<JointState*>(state);
  const MatingPose device = MatingPoseOf(part);
  const double depth = device.depth - options_.depth_origin;
  const Eigen::Vector2d device_offset = device.offset;
  const double device_arc = lever_ * device.angle;
  const bool hand = std::isfinite(options_.proxy_stiffness);
  const bool settle = part.settle_load.squaredNorm() > 0.0;
  // Which coordinates balance: the offset for a hand or under a load, the twist where free.
  const bool free_offset = hand || settle;
  const bool free_twist = part.free_rotation;
  // Handed over by the positioning stage: the body is where that stage left it.
  if (out->stage != StageId::kConstrained) {
    run->q = Eigen::Vector3d(out->pose.offset.x(), out->pose.offset.y(), lever_ * out->pose.angle);
    run->law = {};
    run->jacobian_valid = false;
  }
  Eigen::Vector3d q = run->q;
  if (!free_offset) q.head<2>() = device_offset;
  if (!free_twist) q.z() = device_arc;
  // The proximal term's anchor: where the current iteration started.
  Eigen::Vector3d anchor = q;
  const double k_spring = hand ? options_.proxy_stiffness : 0.0;
  const Eigen::Vector2d load = hand ? Eigen::Vector2d::Zero() : part.settle_load;
  const double torque = free_twist ? part.applied_torque : 0.0;
  const std::array<bool, 3> active = {free_offset, free_offset, free_twist};

  out->feature_count = static_cast<int>(features_.size());
  out->contact_evaluations = 0;
  Sum sum;
  // The balance's residual: the generalised force on the body in (x, z, arc) at q.
  const auto residual = [&](const Eigen::Vector3d& at) {
    Evaluate(at, depth, part, nullptr, &sum, nullptr);
    Eigen::Vector3d g(sum.wrench.force.x() + load.x(), sum.wrench.force.z() + load.y(),
                      (sum.wrench.torque.y() + torque) / lever_);
    g.head<2>() += k_spring * (device_offset - at.head<2>());
    // A hand's spring holds the offset already; the proximal term holds what nothing else does.
    const Eigen::Vector3d proximal = kProximalStiffness * (anchor - at);
    if (!hand) g.head<2>() += proximal.head<2>();
    g.z() += proximal.z();
    for (int k = 0; k < 3; ++k) {
      if (!active[k]) g[k] = 0.0;
    }
    return g;
  };
  if (free_offset || free_twist) {
    Eigen::Vector3d g = residual(q);
    // Before any feature engages the holder carries the body: no load acts, nothing turns it.
    if (!sum.engaged) {
      q.head<2>() = device_offset;
    }
    // The forces derive from a convex energy (each feature's springs on its convex assembly
    // space or Winkler bed, the load, the spring and the proximal term) whose gradient is -g:
    // every step is a Newton direction (or, where that does not descend, the force itself)
    // searched along to where the force along it vanishes, so the energy falls at every step
    // and kinks between contacts cannot make the iteration cycle.
    for (int iteration = 0; sum.engaged && iteration < kMaxIterations; ++iteration) {
      const double scale = sum.wrench.force.norm() + load.norm() + std::abs(torque) / lever_;
      if (g.lpNorm<Eigen::Infinity>() <= kForceTolerance * (1.0 + scale)) break;
      Eigen::Matrix3d& jacobian = run->jacobian;
      if (!run->jacobian_valid) {
        jacobian.setIdentity();
        for (int k = 0; k < 3; ++k) {
          if (!active[k]) continue;
          Eigen::Vector3d probe = q;
          probe[k] += kDifferenceStep;
          jacobian.col(k) = (residual(probe) - g) / kDifferenceStep;
        }
        run->jacobian_valid = true;
      }
      Eigen::Vector3d step = jacobian.partialPivLu().solve(-g);
      if (!step.allFinite() || !(step.dot(g) > 0.0)) {
        step = g / (kProximalStiffness + k_spring);
      }
      const double length = step.norm();
      if (length > kMaxStep) step *= kMaxStep / length;
      if (step.norm() < kPicometre) break;
      // Along the step the force's component f(t) = g(q + t step) . step falls from f(0) > 0;
      // where it is still positive at t = 1 the whole step is taken, else its root is bracketed
      // in (0, 1) and found by regula falsi with the Illinois modification.
      double t_low = 0.0, f_low = g.dot(step);
      double t = 1.0;
      Eigen::Vector3d g_t = residual(q + step);
      double f_t = g_t.dot(step);
      if (f_t < 0.0) {
        double t_high = 1.0, f_high = f_t;
        int side = 0;
        for (int k = 0; k < kLineSearchSteps; ++k) {
          t = (t_low * f_high - t_high * f_low) / (f_high - f_low);
          g_t = residual(q + t * step);
          f_t = g_t.dot(step);
          if (f_t > 0.0) {
            t_low = t;
            f_low = f_t;
            if (side == 1) f_high *= 0.5;
            side = 1;
          } else {
            t_high = t;
            f_high = f_t;
            if (side == -1) f_low *= 0.5;
            side = -1;
          }
          if (std::abs(f_t) <= kForceTolerance * (1.0 + scale) * step.norm()) break;
        }
      }
      q += t * step;
      // A step that did not halve the residual had a stale or kinked Jacobian: the next one
      // differences afresh.
      const double before = g.norm();
      // The next iteration's anchor is where this one ended: the residual there without the
      // proximal term is the true one (a proximal point iteration, so that a body that nothing
      // but the load moves travels up to the load over k_r each iteration, not each tick).
      g = g_t;
      const Eigen::Vector3d proximal = kProximalStiffness * (anchor - q);
      if (!hand) g.head<2>() -= proximal.head<2>();
      g.z() -= proximal.z();
      for (int k = 0; k < 3; ++k) {
        if (!active[k]) g[k] = 0.0;
      }
      anchor = q;
      if (!(g.norm() < 0.5 * before)) run->jacobian_valid = false;
    }
  }
  run->q = q;
  out->contact_evaluations = sum.evaluations;
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  Evaluate(q, depth, part, run->law.data(), &sum, out);
  out->contact_evaluations = sum.evaluations;
  out->wrench = sum.wrench;
  if (hand) {
    // The device feels the coupling spring across the axis (at the balance, the contact's push).
    out->wrench.force.x() = k_spring * (q.x() - device_offset.x());
    out->wrench.force.z() = k_spring * (q.y() - device_offset.y());
  }
  out->pose.depth = depth;
  out->pose.offset = q.head<2>();
  out->pose.angle = q.z() / lever_;
  out->stiffness = hand && out->contact.engaged ? k_spring : 0.0;
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  out->next = depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
}

}  // namespace fitfeel
