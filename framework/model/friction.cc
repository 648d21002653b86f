#include "framework/model/friction.h"

#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace fitfeel {

StickSlipFriction::StickSlipFriction(const FrictionParameters& p) : parameters_(p) {
  if (!std::isfinite(p.static_coefficient) || !std::isfinite(p.kinetic_coefficient) ||
      !(p.kinetic_coefficient >= 0.0) || !(p.static_coefficient >= p.kinetic_coefficient)) {
    throw UserError("friction needs 0 <= kinetic coefficient <= static coefficient (got static " +
                    std::to_string(p.static_coefficient) + ", kinetic " +
                    std::to_string(p.kinetic_coefficient) + ")");
  }
  if (!std::isfinite(p.breakaway_displacement) || !(p.breakaway_displacement > 0.0)) {
    throw UserError("friction needs a positive breakaway displacement");
  }
}

double StickSlipFriction::StickingStiffness(double normal) const noexcept {
  if (!(normal > 0.0) || !std::isfinite(normal)) return 0.0;
  return parameters_.static_coefficient * normal / parameters_.breakaway_displacement;
}

Eigen::Vector2d StickSlipFriction::Step(const Eigen::Vector2d& position, double normal,
                                        FrictionState* state) const noexcept {
  const double k = StickingStiffness(normal);
  if (!(k > 0.0)) {
    // Nothing pressed: the junctions let go, and the next contact forms where it happens.
    state->anchor = position;
    state->anchored = false;
    state->sliding = false;
    return Eigen::Vector2d::Zero();
  }
  if (!state->anchored) {
    state->anchor = position;
    state->anchored = true;
    state->sliding = false;
  }
  const double z_s = parameters_.breakaway_displacement;
  const double z_k = z_s * parameters_.kinetic_coefficient / parameters_.static_coefficient;
  const Eigen::Vector2d deflection = position - state->anchor;
  const double length = deflection.norm();
  // A slip continues only while the part drags the anchor further; the relative 1e-9 keeps a part
  // that stopped exactly at the kinetic deflection (rounded) from counting as still sliding.
  const double limit = (state->sliding ? z_k : z_s) + 1e-9 * z_s;
  if (length > limit) {
    state->anchor = position - (z_k / length) * deflection;
    state->sliding = true;
  } else {
    state->sliding = false;
  }
  return -k * (position - state->anchor);
}

Eigen::Vector2d StickSlipFriction::Smoothed(const Eigen::Vector2d& velocity,
                                            double normal) const noexcept {
  if (!(normal > 0.0) || !std::isfinite(normal)) return Eigen::Vector2d::Zero();
  const double speed = velocity.norm();
  // tanh(s / v_s) / s, continuous at rest (limit 1 / v_s).
  const double per_speed = speed > 1e-12 * kFrictionSmoothingVelocity
                               ? std::tanh(speed / kFrictionSmoothingVelocity) / speed
                               : 1.0 / kFrictionSmoothingVelocity;
  return -parameters_.kinetic_coefficient * normal * per_speed * velocity;
}

}  // namespace fitfeel
