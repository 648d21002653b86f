#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/config_node.h"
#include "framework/model/model_settings.h"
#include "framework/model/surface_options.h"

namespace fitfeel::thread {

// How the flank load spreads over the engaged turns.
enum class LoadDistribution {
  // Every engaged flank cell carries the pressure its interference gives (rigid bolt core and nut
  // body): the load is uniform over the turns.
  kUniform,
  // Sopwith's shear-lag distribution (Proc. IMechE 159, 1948): the bolt core stretches and the nut
  // body compresses under the load they pass to the flanks, so the turn at the bearing face
  // carries most (docs/threads.md).
  kSopwith,
};

// The bolted joint a nut or a bolt head is tightened into (`model.options.joint`): its bearing
// face's annulus, where it meets the clamped part, the friction there and the compliance of the
// bolt's free sections and of the clamped plates, in series with the engaged thread (VDI 2230
// Part 1). Absent: the thread runs freely along the whole bolt.
struct JointOptions {
  // Insertion depth at which the bearing face meets the clamped part (the run-down length), m.
  double seat = std::numeric_limits<double>::infinity();
  double bearing_diameter = 0.0;  // d_W, outer diameter of the bearing annulus, m (0: ISO 4032)
  double hole_diameter = 0.0;     // d_h, the clamped part's hole, m (0: ISO 273 medium)
  double bearing_friction = 0.0;  // mu_K
  std::vector<double> plates;     // thicknesses of the clamped plates, m (their sum is l_K)
  // Outer diameter of the clamped plates about the bolt, D_A, m (VDI 2230's cone angle depends
  // on it).
  double plate_outer_diameter = 0.0;
  double plate_modulus = 0.0;  // E_P, Pa (0: the bolt's)
  // Unthreaded shank length within the clamp, m (0: a fully threaded ISO 4017 bolt).
  double shank = 0.0;
  // The bolt's ISO 898-1 property class ("8.8", "10.9", "12.9"): its yield strength bounds the
  // elastic-limit check. Empty: no check.
  std::string property_class;
  // Given instead of VDI 2230's, N/m (0: computed).
  double stiffness = 0.0;
  bool present() const { return std::isfinite(seat); }
  double clamp_length() const;
};

struct ThreadOptions final : SurfaceOptions {
  LoadDistribution distribution = LoadDistribution::kUniform;
  JointOptions joint;
};

std::shared_ptr<const ThreadOptions> ParseThreadOptions(const ConfigNode& options);
ThreadOptions ThreadOptionsOf(const ModelSettings& settings);

}  // namespace fitfeel::thread
