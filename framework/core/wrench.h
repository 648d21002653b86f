#pragma once

#include <Eigen/Core>

namespace fitfeel {

// Force (N) and torque (N*m) on a body, expressed in a stated frame.
struct Wrench {
  Eigen::Vector3d force{0.0, 0.0, 0.0};
  Eigen::Vector3d torque{0.0, 0.0, 0.0};

  void SetZero() {
    force.setZero();
    torque.setZero();
  }
  bool AllFinite() const { return force.allFinite() && torque.allFinite(); }
};

}  // namespace fitfeel
