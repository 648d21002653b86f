#pragma once

#include <limits>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "framework/model/discretizer.h"
#include "framework/model/friction.h"
#include "framework/model/surface_options.h"
#include "framework/model/variation_generator.h"

namespace fitfeel {

// The largest depth tables a contact analyzer builds (their rows are depth steps along the mating
// axis, each with up to columns + 4 polygon vertices): a step far finer than the grid's rows buys
// nothing, since cells are piecewise constant, and 1e8 vertices are 1.6 GB. The scenario loader
// refuses a depth_step beyond them, the analyzers never build one.
inline constexpr double kMaxDepthSteps = 2e6;
inline constexpr double kMaxDepthTableVertices = 1e8;

// The scenario's `model` section, in SI.
struct ModelSettings {
  std::string law;               // law name offered by the surface type ("gps", "ve1", ...)
  double friction = 0.0;         // Coulomb (kinetic, sliding) coefficient mu_k
  double static_friction = 0.0;  // breakaway coefficient mu_s >= mu_k
  double breakaway_displacement = kSteelBreakawayDisplacement;  // m (friction.h)
  double contact_stiffness = 0.0;                               // k_p, N/m (eq. 9)
  Resolution resolution;                                        // m x n, or auto
  TextureMode texture = TextureMode::kExpected;
  double depth_step = 0.0;  // tabulation step along the mating axis, m (0 = auto)
  // The surface type's `model.options`, parsed at load (SurfaceType::ParseOptions); null: the
  // scene gave none, and the surface's objects take their defaults (OptionsAs).
  std::shared_ptr<const SurfaceOptions> options;
  // The tilt the device holds the moving part at for the whole run (Device::held_tilt): the (x, z)
  // components of the rotation vector that turns the mating axis onto the part's, rad. Zero: the
  // part is aligned. An analyzer that tabulates its contact by depth prepares it for this tilt
  // (ContactAnalyzer::takes_held_tilt); the runtime refuses a tilt for one that does not.
  Eigen::Vector2d held_tilt{0.0, 0.0};
  // How stiffly the holder keeps that tilt (Device::held_tilt_stiffness), N*m/rad: infinite for a
  // rigid holder, whose part stays at the tilt; finite for a compliant one, whose part the contact
  // turns towards the axis once it touches at two points (ContactAnalyzer::takes_compliant_tilt).
  double held_tilt_stiffness = std::numeric_limits<double>::infinity();
  // The deepest mating depth the run's device can take the part to (Device::reach), m; +inf:
  // unbounded. An analyzer that tabulates by depth may stop its tables past it; a pose deeper than
  // it is then answered as out of engagement, so only the run whose device bounded it may use it.
  double reach = std::numeric_limits<double>::infinity();
  // The largest turn |angle| about the mating axis the run's device gives the part
  // (Device::angular_reach), rad; +inf: unbounded. An analyzer that tabulates by the turn may
  // stop its tables past it, under the same rule as `reach`.
  double angular_reach = std::numeric_limits<double>::infinity();
};

// The stick-slip parameters a law builds its friction from. mu_s below mu_k (settings made in
// code that set only `friction`) is taken as mu_s = mu_k: Coulomb friction with stiction.
inline FrictionParameters FrictionOf(const ModelSettings& s) {
  return {s.static_friction > s.friction ? s.static_friction : s.friction, s.friction,
          s.breakaway_displacement};
}

}  // namespace fitfeel
