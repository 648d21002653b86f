#pragma once

#include <cstdint>

#include "framework/core/export.h"
#include "framework/model/friction.h"
#include "framework/stability/hand_experiment.h"

namespace fitfeel {

// Stiction at the device: the stability experiments' hand (hand_experiment.h) held by a
// stick-slip contact (framework/model/friction.h) under a constant normal force instead of
// pressed against a wall. The contact's force goes through a real SafetyChain, direct or through
// the virtual coupling; the stiffness hint, when given, is the junctions' stiffness.
//
// A push below mu_s N (scaled to the device) must leave the hand at rest, held by the junctions'
// spring in series with the coupling, with the oscillation energy of its start decaying; a push
// above it must slide against mu_k N while the contact only takes energy out of the hand.
struct StictionExperiment : HandExperiment {
  StictionExperiment() { method = RenderingMethod::kCoupled; }
  FrictionParameters friction;
  double normal_force = 0.0;  // physical N, constant
};

struct StictionOutcome {
  double displacement = 0.0;  // hand position at the end, m (it starts at rest at 0)
  double final_speed = 0.0;   // |v| at the end, m/s
  bool sliding = false;       // the contact was slipping at the last sample
  // Oscillation energy about the held rest position (m v^2 / 2 + K_s (y - y_rest)^2 / 2, K_s the
  // static stiffness the hand feels): at the start and the largest over the last tenth.
  double initial_energy = 0.0;
  double final_energy = 0.0;
  bool stable = false;        // stuck cases: final < initial
  // Work the rendered force did on the hand over the run, J: at most the junctions' stored
  // energy mu_s N z_s / 2 (scaled) for a passive rendering; negative while sliding.
  double contact_work = 0.0;
  double stored_bound = 0.0;  // that bound, J
  double peak_force = 0.0;    // largest |device force|, N
  std::uint64_t non_finite = 0;
};

// Throws UserError for parameters out of range (as RunWallExperiment).
FITFEEL_API StictionOutcome RunStictionExperiment(const StictionExperiment& experiment);

}  // namespace fitfeel
