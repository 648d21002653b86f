#include "framework/runtime/joint_stage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "framework/core/error.h"
#include "framework/core/root_finding.h"
#include "framework/runtime/contact_search.h"
#include "framework/runtime/joint_lead_in.h"
#include "framework/scenario/joint_frame.h"

namespace fitfeel {

// One feature's share of the summed wrench at a pose, as the Jacobian reads it.
struct JointStage::Share {
  // Its share of the balance's generalised force on (x, z, lever * twist): its force across the
  // axis and its torque about the body's reference axis over the lever.
  Eigen::Vector3d Generalised(double lever) const {
    return {force.x(), force.y(), (torque + arm.y() * force.x() - arm.x() * force.y()) / lever};
  }

  double twist = 0.0;                  // the body's, rad
  Eigen::Vector2d relative{0.0, 0.0};  // its moving axis from its fixed one, joint frame
  Eigen::Vector2d arm{0.0, 0.0};       // its moving axis from the body's reference axis
  Eigen::Vector2d force{0.0, 0.0};     // its force across the axis, joint frame
  double torque = 0.0;                 // its own torque about its axis
  bool pushes = false;                 // in contact: its wrench changes with its offset
};

// The summed wrench on the moving body about its reference axis (scene frame), as a balance reads
// it.
struct JointStage::Sum {
  Eigen::Vector3d at{0.0, 0.0, 0.0};  // the pose (x, z, lever * twist)
  Wrench wrench;
  int evaluations = 0;
  bool engaged = false;  // some feature's surfaces overlap axially
  std::array<Share, kMaxJointFeatures> share;
  // Each feature's contact there (one per feature, kept by the run): the tick's last evaluation
  // of the balance is where it ends, and its contacts serve the run's wrench.
  ContactState* contact = nullptr;
};

// What a run of the stage keeps from tick to tick.
struct JointStage::RunState final : StageState {
  Eigen::Vector3d q{0.0, 0.0, 0.0};  // offset (x, z), lever * twist
  // The balance's last Jacobian, reused on later iterations and ticks while the same features
  // push and its steps land (the contacts' stiffness changes only where one starts or ends, or
  // slides onto another wall): which features pushed where it was taken, and each one's share
  // of it, differenced on its own.
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Identity();
  bool jacobian_valid = false;
  std::array<bool, kMaxJointFeatures> jacobian_pushes{};
  std::array<Eigen::Matrix3d, kMaxJointFeatures> feature_jacobian;
  // Each share's differences against the feature's own relative offset, before the carry
  // through its placement: the wall it pushes on where the Jacobian was taken.
  std::array<Eigen::Matrix<double, 3, 2>, kMaxJointFeatures> feature_differences;
  std::array<LawState, kMaxJointFeatures> law;
  // The tick's work space, kept here so that a tick initialises none of it: the contacts of the
  // balance's last evaluation, and the pose and shares of the evaluation beyond a kink where the
  // last line search stopped short of it.
  std::array<ContactState, kMaxJointFeatures> contacts;
  Eigen::Vector3d beyond_at{0.0, 0.0, 0.0};
  std::array<Share, kMaxJointFeatures> beyond;
  // A hand's body along the axis (AxialBalance): its joint depth and the time of that tick.
  double body_depth = 0.0;
  double body_time = 0.0;
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
// Finite-difference step of the Jacobian, m, taken on each feature's relative offset (micrometres)
// into its contact: exact for the laws' piecewise-linear springs away from a kink, far above the
// rounding of the offset (k h ~ 0.03 N against forces of newtons for N/nm walls), and inside the
// tenths of a nanometre a load of newtons presses a N/nm wall, where a step of a nanometre
// leaves a contact that holds the body and a step out of it crosses its kink.
constexpr double kDifferenceStep = 1e-11;
// A balance is reached where the residual force is below this fraction of the forces at play
// along the free coordinates (the contacts', the load's and the torque's at the lever), plus
// this much of a newton.
constexpr double kForceTolerance = 1e-6;
// The share of an iteration's residual that its step may leave on a Jacobian kept from an
// earlier iteration; more, and the next one differences afresh. On the piecewise-linear contacts
// a current Jacobian leaves rounding; one that leaves a third or a half (a contact's stiffness
// where it has slid onto another wall) would only be refreshed after many short steps.
constexpr double kJacobianMiss = 0.1;
// Regula falsi steps of one line search at most.
constexpr int kLineSearchSteps = 6;

// `jacobian` with the rows and columns of the held coordinates zeroed.
Eigen::Matrix3d Masked(const Eigen::Matrix3d& jacobian, const std::array<bool, 3>& active) {
  Eigen::Matrix3d masked = jacobian;
  for (int k = 0; k < 3; ++k) {
    if (active[k]) continue;
    masked.row(k).setZero();
    masked.col(k).setZero();
  }
  return masked;
}

// One piece of a round feature's contact (one without a torque of its own about its axis), as a
// step past a kink reads it: the force across the axis is affine in the feature's relative
// offset u on the piece, f + D (u - u0), with D its differences at u0. Where the axis is nearest
// an edge of the assembly polygon, D is stiff along the edge's normal alone and the force
// vanishes on the edge's line, the wall; where it is nearest a vertex, D is alike in every
// direction and the force vanishes at the vertex. Between (two depth steps' polygons blended,
// one at a vertex and the other on an edge), neither.
struct Piece {
  // Reads the piece from its differences `d` (force x, z and own torque against u) and its force
  // `f` at u0, `at` = u0 - u_ref from the point its wall or vertex is placed from; false where it
  // has a torque of its own or no stiffness.
  bool Read(const Eigen::Matrix<double, 3, 2>& d, const Eigen::Vector2d& f, double torque,
            const Eigen::Vector2d& at) {
    if (torque != 0.0 || d.row(2).squaredNorm() != 0.0) return false;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> square;
    square.computeDirect(d.topRows<2>().transpose() * d.topRows<2>());
    const Eigen::Vector2d values = square.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    stiffness = values.y();
    if (!(stiffness > 0.0)) return false;
    vertex = values.x() >= (1.0 - kJacobianMiss) * stiffness;
    wall = values.x() <= kJacobianMiss * stiffness;
    if (vertex) {
      point = at - d.topRows<2>().inverse() * f;
    } else {
      // normal . w = offset, where the force's part along its stiffest direction vanishes.
      normal = square.eigenvectors().col(1);
      const Eigen::Vector2d along = d.topRows<2>() * normal / stiffness;
      offset = normal.dot(at) - along.dot(f) / stiffness;
    }
    return point.allFinite() && std::isfinite(offset);
  }

  // Where this piece's wall meets the next piece beyond a kink, from u_ref: the crossing of two
  // walls, or the vertex the piece beyond is held at; false where this piece is no wall, or
  // there is no such point (parallel walls, a piece beyond that is neither).
  bool Meets(const Piece& beyond, Eigen::Vector2d* w) const {
    if (!wall) return false;
    if (beyond.vertex) {
      *w = beyond.point;
      return true;
    }
    if (!beyond.wall) return false;
    Eigen::Matrix2d walls;
    walls << normal.transpose(), beyond.normal.transpose();
    // Walls within a milliradian of parallel (one wall differenced twice) meet nowhere near.
    if (!(std::abs(walls.determinant()) > 1e-3)) return false;
    *w = walls.inverse() * Eigen::Vector2d(offset, beyond.offset);
    return w->allFinite();
  }

  double stiffness = 0.0;            // along its stiffest direction, N/m
  bool wall = false;                 // stiff along that direction alone
  bool vertex = false;               // alike in every direction
  Eigen::Vector2d point{0.0, 0.0};   // a vertex's, from u_ref
  Eigen::Vector2d normal{1.0, 0.0};  // a wall's line: normal . w = offset
  double offset = 0.0;
};

}  // namespace

JointStage::JointStage(std::vector<JointFeature> features, const Options& options)
    : features_(std::move(features)), options_(options) {
  if (features_.empty() || features_.size() > static_cast<std::size_t>(kMaxJointFeatures)) {
    throw UserError("joint stage: 1 to " + std::to_string(kMaxJointFeatures) + " features, not " +
                    std::to_string(features_.size()));
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
  auto state = std::make_unique<RunState>();
  state->feature_jacobian.fill(Eigen::Matrix3d::Zero());
  state->feature_differences.fill(Eigen::Matrix<double, 3, 2>::Zero());
  return state;
}

bool JointStage::FeatureWrench(std::size_t i, const Eigen::Vector2d& relative, double twist,
                               double depth, const PartState& part, LawState* state,
                               bool contact_known, ContactState* contact,
                               Wrench* wrench) const noexcept {
  const JointFeature& f = features_[i];
  const double c = feature_cos_[i], s = feature_sin_[i];
  // The feature's pose in its own frame (the joint frame turned by f.angle).
  MatingPose pose;
  pose.depth = depth - f.engages_after;
  pose.offset = TurnAboutAxis(relative, c, -s);
  pose.angle = twist;
  const bool outer = f.moving == Role::kOuter;
  const Eigen::Vector3d reflect(1.0, 1.0, -1.0);
  if (!contact_known) f.analyzer->Evaluate(AnalyzerPose(pose, f.moving), contact);
  MatingMotion motion;
  const Eigen::Vector2d v =
      TurnAboutAxis(Eigen::Vector2d(part.velocity.x(), part.velocity.z()), c, -s);
  motion.velocity = Eigen::Vector3d(v.x(), part.velocity.y(), v.y());
  motion.angular_velocity = part.angular_velocity;
  if (outer) {
    motion.velocity = motion.velocity.cwiseProduct(reflect);
    motion.angular_velocity = motion.angular_velocity.cwiseProduct(reflect);
  }
  motion.depth = pose.depth;
  motion.angle = pose.angle;
  Wrench w;
  if (state == nullptr) {
    f.law->Evaluate(*contact, motion, &w);
  } else {
    // Out of engagement the junctions let go, so a re-entry forms its contact afresh.
    if (!contact->engaged) *state = LawState{};
    f.law->Evaluate(*contact, motion, state, &w);
  }
  if (outer) {
    w.force = w.force.cwiseProduct(reflect);
    w.torque = w.torque.cwiseProduct(reflect);
  }
  // Before its surfaces overlap, a feature's moving part may meet its lead-in: the hub's keyway
  // the key's end, a plate's second hole its pin's chamfer.
  bool on_lead_in = false;
  if (pose.depth < 0.0 && !f.lead_in.empty()) {
    const LeadInPush push = PushOfLeadIn(f.lead_in, pose.depth + f.lead_in.capture_depth(),
                                         pose.offset, f.lead_in_stiffness);
    w.force += Eigen::Vector3d(push.across.x(), push.axial, push.across.y());
    on_lead_in = push.touching;
  }
  // Back into the joint frame.
  const Eigen::Vector2d fxz = TurnAboutAxis(Eigen::Vector2d(w.force.x(), w.force.z()), c, s);
  const Eigen::Vector2d txz = TurnAboutAxis(Eigen::Vector2d(w.torque.x(), w.torque.z()), c, s);
  wrench->force = Eigen::Vector3d(fxz.x(), w.force.y(), fxz.y());
  wrench->torque = Eigen::Vector3d(txz.x(), w.torque.y(), txz.y());
  return on_lead_in;
}

void JointStage::Evaluate(const Eigen::Vector3d& q, double depth, const PartState& part,
                          LawState* states, Sum* sum, StageOutput* out) const noexcept {
  // The contacts of the last evaluation where it was at the same pose (the same tick).
  const bool contacts_known = sum->evaluations > 0 && sum->at == q;
  sum->at = q;
  sum->wrench.SetZero();
  sum->engaged = false;
  const double twist = q.z() / lever_;
  const double twist_c = std::cos(twist), twist_s = std::sin(twist);
  const Eigen::Vector2d offset = q.head<2>();
  for (std::size_t i = 0; i < features_.size(); ++i) {
    const JointFeature& f = features_[i];
    // Where the feature's moving axis is, from the body's reference axis and from the feature's
    // fixed axis.
    const Eigen::Vector2d arm = TurnAboutAxis(f.moving_axis, twist_c, twist_s);
    const Eigen::Vector2d relative = offset + arm - f.fixed_axis;
    ContactState& contact = sum->contact[i];
    Wrench w;
    const bool on_lead_in =
        FeatureWrench(i, relative, twist, depth, part, states == nullptr ? nullptr : &states[i],
                      contacts_known, &contact, &w);
    if (!contacts_known) ++sum->evaluations;
    sum->engaged = sum->engaged || contact.engaged || on_lead_in;
    // About the body's reference axis.
    const Eigen::Vector3d lever_arm(arm.x(), 0.0, arm.y());
    sum->wrench.force += w.force;
    sum->wrench.torque += w.torque + lever_arm.cross(w.force);
    Share& share = sum->share[i];
    share.twist = twist;
    share.relative = relative;
    share.arm = arm;
    share.force = Eigen::Vector2d(w.force.x(), w.force.z());
    share.torque = w.torque.y();
    share.pushes =
        share.force != Eigen::Vector2d::Zero() || share.torque != 0.0 || contact.interference;
    if (out != nullptr) {
      out->feature_axial[i] = w.force.y();
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

Eigen::Matrix<double, 3, 2> JointStage::FeatureDifferences(std::size_t i, const Share& share,
                                                           double depth, const PartState& part,
                                                           int* evaluations) const noexcept {
  // Its wrench (force across the axis, own torque) against its relative offset u, differenced
  // along two directions: where it pushes, into its contact (against its force: a step out of a
  // contact pressed a fraction of a nanometre would cross its kink) and along the contact;
  // otherwise along x and z.
  const Eigen::Vector3d at(share.force.x(), share.force.y(), share.torque);
  Eigen::Matrix2d basis = Eigen::Matrix2d::Identity();
  const double push = share.force.norm();
  if (push > 0.0) {
    const Eigen::Vector2d into = -share.force / push;
    basis.col(0) = into;
    basis.col(1) = Eigen::Vector2d(-into.y(), into.x());
  }
  Eigen::Matrix<double, 3, 2> along;  // d(wrench)/d(u) along the basis' columns
  for (int k = 0; k < 2; ++k) {
    ContactState contact;
    Wrench w;
    FeatureWrench(i, share.relative + kDifferenceStep * basis.col(k), share.twist, depth, part,
                  nullptr, false, &contact, &w);
    ++*evaluations;
    along.col(k) = (Eigen::Vector3d(w.force.x(), w.force.z(), w.torque.y()) - at) / kDifferenceStep;
  }
  // The basis is orthonormal: d/du = along * basis^T.
  return along * basis.transpose();
}

void JointStage::AddCarried(const Eigen::Matrix<double, 3, 2>& d_u, const Share& share,
                            Eigen::Matrix3d* jacobian) const noexcept {
  // u = o + R(theta) a - b: du/dq = [I, perp(arm) / lever] with perp(arm) = (arm_z, -arm_x), the
  // arm's derivative along the twist. The twist the feature's analyzer also reads (its pose's
  // angle) is not differenced: the shipped analyzers ignore it, and a Jacobian that misses it
  // costs a line search, not the balance.
  Eigen::Matrix<double, 2, 3> u_q;
  u_q.leftCols<2>().setIdentity();
  u_q.col(2) = Eigen::Vector2d(share.arm.y(), -share.arm.x()) / lever_;
  const Eigen::Matrix<double, 2, 3> force_q = d_u.topRows<2>() * u_q;
  const Eigen::Matrix<double, 1, 3> torque_q = d_u.row(2) * u_q;
  jacobian->topRows<2>() += force_q;
  // The torque about the reference axis, (T + arm_z F_x - arm_x F_z) / lever: its force's share
  // through the arm, and the arm's own turn with the twist (-arm . F / lever^2).
  jacobian->row(2) +=
      (torque_q + share.arm.y() * force_q.row(0) - share.arm.x() * force_q.row(1)) / lever_;
  (*jacobian)(2, 2) -= share.arm.dot(share.force) / (lever_ * lever_);
}

double JointStage::AxialBalance(double device_depth, const Eigen::Vector3d& q,
                                const PartState& part, RunState* run,
                                int* evaluations) const noexcept {
  const double k = options_.proxy_stiffness;
  const double from = run->body_depth;
  if (device_depth == from) return from;
  // The tick's period, for the body's velocity (a device's first tick: 1 ms, the scenes' rate).
  const double period = part.time > run->body_time ? part.time - run->body_time : 1e-3;
  PartState moving = part;
  Sum sum;
  sum.contact = run->contacts.data();
  // g(d) = k (device - d) + F_y(d): the spring's pull on the body at depth d and the features'
  // axial force there with the body moving from `from` to d in one tick (the history-free
  // friction, smoothed in the velocity, and the lead-ins' faces). g falls with d: the friction
  // resists the way the body moves and the faces push back the deeper it goes; at `from` it has
  // the spring's sign and at the device the resistance's, so one root lies between.
  const auto g = [&](double d) {
    moving.velocity.y() = (d - from) / period;
    sum.evaluations = 0;
    Evaluate(q, d, moving, nullptr, &sum, nullptr);
    *evaluations += sum.evaluations;
    return k * (device_depth - d) + sum.wrench.force.y();
  };
  // To a micronewton of the spring's pull (and a picometre of depth).
  const double tolerance = 1e-6 * (1.0 + k * std::abs(device_depth - from));
  // The body mostly lags the device by the resistance over the spring's stiffness: one step from
  // the device by that lag (kept between the two depths) lands on the root where the resistance
  // changes little over the lag, the usual tick; the bracket and its search only where not.
  const double at_device = g(device_depth);
  if (std::abs(at_device) <= tolerance) return device_depth;
  const double lagged = std::clamp(device_depth + at_device / k, std::min(from, device_depth),
                                   std::max(from, device_depth));
  const double at_lagged = g(lagged);
  if (std::abs(at_lagged) <= tolerance) return lagged;
  if ((at_lagged > 0.0) != (at_device > 0.0)) {
    return IllinoisRoot(g, lagged, device_depth, at_lagged, at_device, tolerance, kAxialSteps);
  }
  const double at_from = g(from);
  if ((at_from > 0.0) == (at_lagged > 0.0)) {
    return std::abs(at_from) < std::abs(at_lagged) ? from : lagged;
  }
  return IllinoisRoot(g, from, lagged, at_from, at_lagged, tolerance, kAxialSteps);
}

bool JointStage::OnPolygon(std::size_t i, const Share& near, const Eigen::Vector2d& w, double depth,
                           const PartState& part, int* evaluations) const noexcept {
  ContactState contact;
  Wrench wrench;
  FeatureWrench(i, near.relative + w, near.twist, depth, part, nullptr, false, &contact, &wrench);
  ++*evaluations;
  return Eigen::Vector2d(wrench.force.x(), wrench.force.z()).norm() <=
         kJacobianMiss * near.force.norm();
}

void JointStage::DoEvaluate(const PartState& part, StageState* state,
                            StageOutput* out) const noexcept {
  auto* run = static_cast<RunState*>(state);
  const MatingPose device = MatingPoseOf(part);
  const double device_depth = device.depth - options_.depth_origin;
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
    run->body_depth = out->pose.depth;
    run->body_time = part.time;
  }
  out->contact_evaluations = 0;
  // A hand's body is a god object along the axis too: it follows the device's depth only as
  // far as the coupling spring overcomes the features' resistance (a jammed plate stays where it
  // jammed and the hand feels the spring, not the contacts' kilonewtons); a robot's is at the
  // device's depth.
  int axial_evaluations = 0;
  const double depth =
      hand ? AxialBalance(device_depth, run->q, part, run, &axial_evaluations) : device_depth;
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
  // The proximal term's stiffness along each coordinate: a hand's spring holds the offset
  // already, the proximal term holds what nothing else does, and a held coordinate is not
  // balanced.
  Eigen::Vector3d proximal_stiffness(hand ? 0.0 : kProximalStiffness,
                                     hand ? 0.0 : kProximalStiffness, kProximalStiffness);
  for (int k = 0; k < 3; ++k) {
    if (!active[k]) proximal_stiffness[k] = 0.0;
  }
  Sum sum;
  sum.contact = run->contacts.data();
  // The balance's residual: the generalised force on the body in (x, z, arc) at q.
  const auto residual = [&](const Eigen::Vector3d& at) {
    Evaluate(at, depth, part, nullptr, &sum, nullptr);
    Eigen::Vector3d g(sum.wrench.force.x() + load.x(), sum.wrench.force.z() + load.y(),
                      (sum.wrench.torque.y() + torque) / lever_);
    g.head<2>() += k_spring * (device_offset - at.head<2>());
    g += proximal_stiffness.cwiseProduct(anchor - at);
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
    // Where the last line search stopped short of a kink of the contacts (a contact that starts,
    // a wall that turns): its evaluation beyond the root.
    const std::size_t n = features_.size();
    std::array<Share, kMaxJointFeatures>& beyond = run->beyond;
    bool kinked = false;
    // Whether the last step was modelled on a vertex and overshot all the same: the walls
    // differenced on either side of the kink met elsewhere than the body turns (two depth steps'
    // polygons blended, each with a vertex of its own), and the next kink is modelled without.
    bool corner_missed = false;
    // The forces derive from a convex energy (each feature's springs on its convex assembly
    // space or Winkler bed, the load, the spring and the proximal term) whose gradient is -g:
    // every step is a Newton direction (or, where that does not descend, the force itself)
    // searched along to where the force along it vanishes, so the energy falls at every step
    // and kinks between contacts cannot make the iteration cycle.
    for (int iteration = 0; sum.engaged && iteration < kMaxIterations; ++iteration) {
      // The forces at play along the free coordinates (the contacts' along a held one go to the
      // holder): the contacts', the load's and the torque's at the lever.
      Eigen::Vector3d contacts(sum.wrench.force.x(), sum.wrench.force.z(),
                               sum.wrench.torque.y() / lever_);
      for (int k = 0; k < 3; ++k) {
        if (!active[k]) contacts[k] = 0.0;
      }
      const double scale = contacts.norm() + load.norm() + std::abs(torque) / lever_;
      if (g.lpNorm<Eigen::Infinity>() <= kForceTolerance * (1.0 + scale)) break;
      // The contacts' stiffness is kept while the same ones push and its steps land (below);
      // it changes only where a contact starts or ends, or slides onto another wall.
      std::array<bool, kMaxJointFeatures> pushes{};
      for (std::size_t i = 0; i < features_.size(); ++i) pushes[i] = sum.share[i].pushes;
      Eigen::Matrix3d& jacobian = run->jacobian;
      if (pushes != run->jacobian_pushes) run->jacobian_valid = false;
      if (!run->jacobian_valid) {
        // The features' shares by their own differences, then the terms that are linear in q:
        // the spring and the proximal term (the load and the torque are constant).
        jacobian.setZero();
        for (std::size_t i = 0; i < features_.size(); ++i) {
          Eigen::Matrix3d& share = run->feature_jacobian[i];
          share.setZero();
          if (pushes[i]) {
            run->feature_differences[i] =
                FeatureDifferences(i, sum.share[i], depth, part, &sum.evaluations);
            AddCarried(run->feature_differences[i], sum.share[i], &share);
          }
          jacobian += Masked(share, active);
        }
        run->jacobian_pushes = pushes;
        jacobian.diagonal() -= Eigen::Vector3d(k_spring, k_spring, 0.0);
        jacobian.diagonal() -= proximal_stiffness;
        // A held coordinate neither moves nor is balanced.
        for (int k = 0; k < 3; ++k) {
          if (!active[k]) jacobian(k, k) = 1.0;
        }
        run->jacobian_valid = true;
      }
      // The contacts are piecewise linear in q, and the step is Newton's on the piece that holds
      // the body. Where the last line search stopped short of a kink (a contact that starts, or
      // one that slides onto another wall), the contacts that kinked are modelled past it: on the
      // piece here alone the step would run into the kink again and the line search creep up to
      // it step by step.
      Eigen::Matrix3d model = jacobian;
      Eigen::Vector3d pushed = g;
      bool cornered = false;
      if (kinked) {
        // The features whose force beyond is not what their piece here predicts. Where one
        // alone kinked, the kink is its own (a corner of its polygon); where several did, their
        // contacts meet each other's (one starts while another slides).
        std::array<bool, kMaxJointFeatures> kinks{};
        int kinking = 0;
        for (std::size_t i = 0; i < n; ++i) {
          if (!beyond[i].pushes) continue;
          const Eigen::Vector3d here = sum.share[i].Generalised(lever_);
          const Eigen::Vector3d there = beyond[i].Generalised(lever_);
          const Eigen::Vector3d predicted = here + run->feature_jacobian[i] * (run->beyond_at - q);
          kinks[i] = (there - predicted).norm() > kJacobianMiss * (there - here).norm();
          kinking += kinks[i] ? 1 : 0;
        }
        for (std::size_t i = 0; i < n; ++i) {
          if (!kinks[i]) continue;
          const Share& near = sum.share[i];
          const Eigen::Matrix<double, 3, 2> d_beyond =
              FeatureDifferences(i, beyond[i], depth, part, &sum.evaluations);
          // Its pieces here and beyond, read where it kinked alone and pushes on both sides, as a
          // round feature does without a torque of its own (a key's flank has one: its pieces are
          // no polygon's about its axis).
          Piece from, past;
          const bool own = kinking == 1 && near.pushes &&
                           from.Read(run->feature_differences[i], near.force, near.torque,
                                     Eigen::Vector2d::Zero()) &&
                           past.Read(d_beyond, beyond[i].force, beyond[i].torque,
                                     beyond[i].relative - near.relative);
          Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();
          Eigen::Vector3d push;
          Eigen::Vector2d to_vertex;
          if (own && !corner_missed && from.Meets(past, &to_vertex) &&
              OnPolygon(i, near, to_vertex, depth, part, &sum.evaluations)) {
            // It slid along a wall past the wall's end, the vertex where the next wall begins
            // (checked on the polygon: walls that are not neighbours, where the step slid past
            // several edges, meet outside it). Past the vertex the axis is pushed back to it
            // alike from every side (the distance from a convex polygon is the distance from a
            // vertex wherever that is the nearest point), and a hand's spring or a load that
            // presses the body into the corner finds its balance there, nanometres off the
            // vertex; along either wall a step would slide past it again. In place of its piece
            // here: the vertex's spring, as stiff as the walls.
            cornered = true;
            const double k = std::max(from.stiffness, past.stiffness);
            Share vertex = near;
            vertex.force = k * to_vertex;
            Eigen::Matrix<double, 3, 2> d_vertex = Eigen::Matrix<double, 3, 2>::Zero();
            d_vertex.topRows<2>().diagonal().setConstant(-k);
            AddCarried(d_vertex, vertex, &stiffness);
            stiffness -= run->feature_jacobian[i];
            push = vertex.Generalised(lever_) - near.Generalised(lever_);
          } else if (own && !from.wall && past.wall) {
            // Held at a vertex here, it slides off onto the wall beyond: in place of its piece
            // here, the wall's.
            AddCarried(d_beyond, beyond[i], &stiffness);
            push = beyond[i].Generalised(lever_) + stiffness * (q - run->beyond_at) -
                   near.Generalised(lever_);
            stiffness -= run->feature_jacobian[i];
          } else {
            // Both sides of the kink: its spring here and the one beyond, whose push here is its
            // force beyond less its stiffness times the way back. A contact about to start is
            // counted before it does, and where two features' walls meet, both hold the body.
            AddCarried(d_beyond, beyond[i], &stiffness);
            push = beyond[i].Generalised(lever_) + stiffness * (q - run->beyond_at);
          }
          model += Masked(stiffness, active);
          for (int k = 0; k < 3; ++k) {
            if (!active[k]) push[k] = 0.0;
          }
          pushed += push;
        }
        // The model is no piece of the contacts': the next iteration differences afresh.
        run->jacobian_valid = false;
        kinked = false;
      }
      Eigen::Vector3d step = model.partialPivLu().solve(-pushed);
      if (!step.allFinite() || !(step.dot(g) > 0.0)) {
        step = g / (kProximalStiffness + k_spring);
      }
      const double length = step.norm();
      if (length > kMaxStep) step *= kMaxStep / length;
      if (step.norm() < kPicometre) break;
      // Along the step the force's component f(t) = g(q + t step) . step falls from f(0) > 0;
      // where it is still positive at t = 1, or negative by no more than the balance's tolerance
      // (a Newton step that lands on the balance), the whole step is taken, else its root is
      // bracketed in (0, 1) and found by regula falsi with the Illinois modification.
      const double line_tolerance = kForceTolerance * (1.0 + scale) * step.norm();
      double t_low = 0.0, f_low = g.dot(step);
      double t = 1.0;
      Eigen::Vector3d g_t = residual(q + step);
      double f_t = g_t.dot(step);
      corner_missed = cornered && f_t < -line_tolerance;
      if (f_t < -line_tolerance) {
        run->beyond_at = sum.at;
        std::copy_n(sum.share.begin(), n, beyond.begin());
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
            run->beyond_at = sum.at;
            std::copy_n(sum.share.begin(), n, beyond.begin());
            if (side == -1) f_low *= 0.5;
            side = -1;
          }
          if (std::abs(f_t) <= line_tolerance) break;
        }
        kinked = f_t > 0.0;
      }
      q += t * step;
      // On a Jacobian of the contacts that hold the body the step lands on this iteration's
      // balance, proximal term included, to within rounding: a step that leaves a tenth of the
      // residual had a stale or kinked one, and the next iteration differences afresh.
      if (!(g_t.norm() < kJacobianMiss * g.norm())) run->jacobian_valid = false;
      // The next iteration's anchor is where this one ended: the residual there without the
      // proximal term is the true one (a proximal point iteration, so that a body that nothing
      // but the load moves travels up to the load over k_r each iteration, not each tick).
      g = g_t - proximal_stiffness.cwiseProduct(anchor - q);
      anchor = q;
    }
  }
  run->q = q;
  out->contact_evaluations = axial_evaluations + sum.evaluations;
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  Evaluate(q, depth, part, run->law.data(), &sum, out);
  out->contact_evaluations = axial_evaluations + sum.evaluations;
  out->wrench = sum.wrench;
  if (hand) {
    // The device feels the coupling spring across the axis (at the balance, the contact's push).
    out->wrench.force.x() = k_spring * (q.x() - device_offset.x());
    out->wrench.force.z() = k_spring * (q.y() - device_offset.y());
    // Along the axis too: at the body's depth its spring's pull is the features' resistance.
    out->wrench.force.y() = k_spring * (depth - device_depth);
    run->body_depth = depth;
    run->body_time = part.time;
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
