#include "framework/safety/passivity_observer.h"

#include <algorithm>
#include <cmath>

namespace fitfeel {

void PassivityObserver::Configure(double device_damping, bool credit_device_damping,
                                  bool controller, double max_damping) {
  device_damping_ = std::max(0.0, device_damping);
  credit_ = credit_device_damping;
  controller_ = controller;
  max_damping_ = std::max(0.0, max_damping);
  Reset(Eigen::Vector3d::Zero());
  started_ = false;
}

void PassivityObserver::Reset(const Eigen::Vector3d& position) noexcept {
  last_position_ = position;
  last_displacement_.setZero();
  held_.setZero();
  started_ = true;
  energy_ = 0.0;
  energy_created_ = 0.0;
  controller_energy_ = 0.0;
  controller_ticks_ = 0;
}

void PassivityObserver::Observe(const Eigen::Vector3d& position, double dt) noexcept {
  if (!started_) {
    Reset(position);
    return;
  }
  const Eigen::Vector3d dx = position - last_position_;
  last_position_ = position;
  last_displacement_ = dx;
  double absorbed = -held_.dot(dx);
  if (credit_ && std::isfinite(dt) && dt > 0.0) absorbed += device_damping_ * dx.squaredNorm() / dt;
  energy_ += absorbed;
  energy_created_ = std::max(energy_created_, -energy_);
}

Eigen::Vector3d PassivityObserver::Control(const Eigen::Vector3d& force, double dt) noexcept {
  if (!controller_ || energy_ >= 0.0 || !(dt > 0.0) || !std::isfinite(dt)) return force;
  const Eigen::Vector3d v = last_displacement_ / dt;
  const double v_sq = v.squaredNorm();
  if (!(v_sq > 0.0)) return force;
  const double alpha = std::min(-energy_ / (dt * v_sq), max_damping_);
  ++controller_ticks_;
  controller_energy_ += alpha * v_sq * dt;
  return force - alpha * v;
}

}  // namespace fitfeel
