#include "framework/safety/virtual_coupling.h"

#include <algorithm>
#include <cmath>

#include "framework/core/demand.h"

namespace fitfeel {
namespace {

constexpr double kStiffnessMargin = 0.8;
constexpr double kDampingShare = 0.5;
// The proxy's positions are computed, not measured, so a secant is meaningful down to where the
// law's force stops being smooth; 1 nm is far below any tolerance the law resolves and far above
// the rounding of positions of a few centimetres.
constexpr double kMinSecantStep = 1e-9;     // m
constexpr double kEstimateDecayTime = 0.1;  // s

}  // namespace

CouplingGains DefaultCouplingGains(const DeviceSpec& spec, double period) {
  FITFEEL_DEMAND(period > 0.0 && spec.damping > 0.0 && spec.max_stiffness > 0.0);
  CouplingGains gains;
  const double bound_stiffness = 2.0 * spec.damping / period;
  gains.stiffness = kStiffnessMargin * std::min(spec.max_stiffness, bound_stiffness);
  gains.damping = kDampingShare * (spec.damping - gains.stiffness * period / 2.0);
  return gains;
}

bool CouplingGainsArePassive(const CouplingGains& gains, const DeviceSpec& spec, double period) {
  return gains.stiffness > 0.0 && gains.damping >= 0.0 && gains.stiffness <= spec.max_stiffness &&
         spec.damping > gains.stiffness * period / 2.0 + std::abs(gains.damping);
}

void VirtualCoupling::Configure(const CouplingGains& gains, double proxy_mass) {
  FITFEEL_DEMAND(gains.stiffness > 0.0 && gains.damping >= 0.0 && proxy_mass >= 0.0);
  gains_ = gains;
  mass_ = proxy_mass;
  Reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

void VirtualCoupling::Reset(const Eigen::Vector3d& device_position,
                            const Eigen::Vector3d& device_velocity) noexcept {
  position_ = device_position;
  velocity_ = device_velocity;
  has_last_ = false;
  last_force_.setZero();
  stiffness_estimate_ = 0.0;
}

Eigen::Vector3d VirtualCoupling::Step(const Eigen::Vector3d& environment_force,
                                      const Eigen::Vector3d& device_position,
                                      const Eigen::Vector3d& device_velocity, double stiffness_hint,
                                      double dt) noexcept {
  // Environment stiffness seen along the proxy's last move (secant), decaying when no move shows
  // it: an overestimate (a friction reversal reads as a huge stiffness) would otherwise hold the
  // proxy forever, while an estimate decayed below half the true stiffness only lets the proxy
  // drift until its move is measurable again, which is sub-nanometre.
  const bool in_contact = environment_force.squaredNorm() > 0.0;
  double measured = 0.0;
  if (has_last_) {
    const Eigen::Vector3d dx = position_ - last_position_;
    const double dx_sq = dx.squaredNorm();
    if (dx_sq > kMinSecantStep * kMinSecantStep) {
      measured = std::max(0.0, -(environment_force - last_force_).dot(dx) / dx_sq);
    }
  }
  stiffness_estimate_ =
      std::max(measured, stiffness_estimate_ * std::exp(-dt / kEstimateDecayTime));
  if (!std::isfinite(stiffness_estimate_)) stiffness_estimate_ = 0.0;
  const bool was_in_contact = has_last_ && last_force_.squaredNorm() > 0.0;
  const Eigen::Vector3d previous_position = last_position_;
  const Eigen::Vector3d previous_force = last_force_;
  const bool crossed = has_last_ && was_in_contact != in_contact;
  last_position_ = position_;
  last_force_ = environment_force;
  has_last_ = true;
  // The linearisation holds only in contact: a proxy the environment does not push is free, and
  // an implicit stiffness there would only hold it back.
  const double k_e = in_contact ? std::max(stiffness_estimate_,
                                           std::isfinite(stiffness_hint) ? stiffness_hint : 0.0)
                                : 0.0;

  const double denominator = mass_ / dt + (k_e + gains_.stiffness) * dt + gains_.damping;
  const Eigen::Vector3d numerator = (mass_ / dt) * velocity_ + environment_force +
                                    gains_.stiffness * (device_position - position_) +
                                    gains_.damping * device_velocity;
  velocity_ = numerator / denominator;
  Eigen::Vector3d step = dt * velocity_;
  // The face of the environment lies between the last two positions when contact began or ended
  // between them. The secant across the face underestimates a stiff environment and the step can
  // overshoot back past the face; bisection keeps the proxy inside that bracket, which shrinks by
  // half at each crossing until both samples lie on one side and the secant is exact.
  if (crossed) {
    const Eigen::Vector3d outward = (in_contact ? environment_force : previous_force).normalized();
    // Along `direction`, how far the step goes towards the previous position, and the bracket.
    const Eigen::Vector3d direction = in_contact ? outward : -outward;
    const double bracket = (previous_position - position_).dot(direction);
    const double along = step.dot(direction);
    if (bracket > 0.0 && along > 0.5 * bracket) {
      step -= (along - 0.5 * bracket) * direction;
      velocity_ = step / dt;
    }
  }
  position_ += step;
  // Reaction of the coupling on the handle: it pulls the handle towards the proxy.
  return gains_.stiffness * (position_ - device_position) +
         gains_.damping * (velocity_ - device_velocity);
}

}  // namespace fitfeel
