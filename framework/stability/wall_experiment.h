#pragma once

#include <cstdint>
#include <string>

#include "framework/core/export.h"
#include "framework/stability/hand_experiment.h"

namespace fitfeel {

// One stability experiment: the hand (hand_experiment.h) pushed into a sampled virtual wall.
//
// The hand arrives at the wall's face (y = 0) at the approach speed. Every sample the wall reads
// the position of the point it acts on and computes
//   F = -K y - B (y_k - y_(k-1)) / T   while y > 0 (0 outside),
// in physical units (K / force_scale, B / force_scale).
//
// Colgate & Schenkel (1997): this wall is passive iff b > K T / 2 + |B|. K and B are the values at
// the device (force_scale times the physical ones).
struct WallExperiment : HandExperiment {
  double stiffness = 0.0;  // K at the device, N/m (> 0)
  double damping = 0.0;    // B at the device, N*s/m (any sign)
  // The paper's insertion speed (4.1); the hand arrives slower when this speed would make it
  // bounce off the wall (see RunWallExperiment).
  double approach_speed = 0.01;  // m/s
};

struct WallOutcome {
  double bound_margin = 0.0;  // b - (K T / 2 + |B|), N*s/m
  bool bound_ok = false;      // bound_margin > 0
  // Energy of the hand above its resting state, E = m v^2 / 2 + U_wall(y) - F_push y, less its
  // value at rest, with U_wall the potential of a one-sided spring of the static stiffness the
  // hand feels (K direct; K_c in series with K coupled) whose force saturates at the device's
  // peak rating. For the continuous wall E only decreases.
  double initial_energy = 0.0;        // J, at the first contact
  double final_energy = 0.0;          // J, largest over the last tenth of the horizon
  double energy_growth = 0.0;         // J, final - initial
  bool stable = false;                // the oscillation energy decayed: final < initial
  double peak_force = 0.0;            // N, largest |force| sent to the device
  double peak_requested_force = 0.0;  // N, before the chain's limits
  double peak_penetration = 0.0;      // m, of the hand past the wall's face
  std::uint64_t ticks = 0;
  std::uint64_t non_finite = 0;  // device forces that were not finite (must stay 0)
};

// Runs one experiment. Throws UserError when a parameter is out of range or the device spec or
// the safety settings are refused by the chain.
FITFEEL_API WallOutcome RunWallExperiment(const WallExperiment& experiment);

// b - (K T / 2 + |B|) for an experiment's values (Colgate & Schenkel).
FITFEEL_API double PassivityMargin(double physical_damping, double stiffness, double damping,
                                   double period);

// The stiffness at which direct rendering's measured stability changes, found by bisection in
// log K between `low` (must be stable) and `high` (must be unstable) to a relative width of
// `tolerance`. Throws UserError when the end points do not bracket a change.
FITFEEL_API double MeasureStabilityBoundary(WallExperiment experiment, double low, double high,
                                            double tolerance = 0.01);

}  // namespace fitfeel
