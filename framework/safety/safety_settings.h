#pragma once

#include <optional>

#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/device/device.h"

namespace fitfeel {

// How the device is connected to the simulated part.
enum class CouplingMode {
  // The law's wrench, scaled and limited, goes straight to the device ("direct rendering"); the
  // law is evaluated at the device's pose. Stable only while the scaled contact stiffness obeys
  // b > K*T/2 + |B| (Colgate & Schenkel 1997), which a press fit never does.
  kDirect,
  // A spring-damper between the device handle and a simulated copy of the moving part (the
  // proxy); the law is evaluated at the proxy's pose (SafetyChain::SimulatedState) and the device
  // feels only the coupling (Colgate, Stanley & Brown 1995; Adams & Hannaford 1999).
  kSpringDamper,
};

// The scenario's `safety` section, in SI. Every field has a default derived from the device spec
// where one exists; nothing is tuned to a curve.
struct SafetySettings {
  // Device newtons per physical newton (also applied to torques: positions are not scaled).
  double force_scale = 1.0;
  // When set, force_scale = spec.max_continuous_force / physical_full_scale, i.e. this physical
  // force is felt at the device's continuous rating.
  std::optional<double> physical_full_scale;
  // The force mapping (framework/safety/force_mapping.h); absent: the device spec's. A scenario
  // that gives force_scale or physical_full_scale chooses kLinear with it.
  std::optional<ForceMappingKind> force_mapping;
  // Perceptual mapping: the knee (scene forces below it are rendered as they are) and the scene
  // force rendered at the device's top, N (kDefaultMappingKnee, kDefaultMappingTop).
  double mapping_knee = 0.1;
  double mapping_top = 20e3;
  // Time constant of the first-order thermal model enforcing the continuous force rating, s.
  // Motor windings of desktop devices have thermal time constants of tens of seconds; 10 s is the
  // conservative end (a shorter constant limits sooner).
  double continuous_window = 10.0;

  CouplingMode coupling = CouplingMode::kSpringDamper;
  // Coupling gains; when absent they are chosen from the device spec (VirtualCouplingGains).
  std::optional<double> coupling_stiffness;  // N/m
  std::optional<double> coupling_damping;    // N*s/m
  // Mass of the proxy in device units, kg; 0 makes the proxy quasi-static (no inertia of its own).
  double proxy_mass = 0.0;

  // A device that renders no torque (3-DOF): the torque about the mating axis given as the force
  // a hand holding the part at this lever arm (the handle along +z from the axis) would feel,
  // T_y / lever along x, through the chain's limits like any force (docs/threads.md). 0: torque
  // passed on as torque.
  double torque_lever = 0.0;  // m

  // Passivity observer (always on) and controller (optional).
  bool credit_device_damping = true;  // count the device's physical damping as dissipation
  bool passivity_controller = false;
  std::optional<double> passivity_max_damping;  // N*s/m; default: the device's damping
};

// Parses the `safety` section:
//   force_scale: 0.01 | physical_full_scale: 300 N    (not both)
//   force_mapping: linear | perceptual                (perceptual: neither of the two above)
//   mapping_knee: 0.1 N       mapping_top: 20 kN      (0 < knee < top)
//   continuous_window: 10 s
//   coupling: spring_damper | direct
//   coupling_stiffness: 800 N/m       coupling_damping: 2 N*s/m       proxy_mass: 0 kg
//   credit_device_damping: true       passivity_controller: false     passivity_max_damping: ...
// Throws ScenarioError at the offending key.
FITFEEL_API SafetySettings ParseSafetySettings(const ConfigNode& node);

// The `safety` section as the scene holds it, parsed at load: the settings, and whether the
// section chose the coupling itself (a device without a motor renders directly unless it did).
struct SafetySection {
  SafetySettings settings;
  bool names_coupling = false;
};
// Throws ScenarioError at the offending key.
FITFEEL_API SafetySection ParseSafetySection(const ConfigNode& node);

}  // namespace fitfeel
