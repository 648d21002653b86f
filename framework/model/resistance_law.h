#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/friction.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"

namespace fitfeel {

// Motion of the moving part in the fixed part's mating frame, for friction: velocities for the
// history-free (smoothed) friction, positions along the mating motions for stick-slip.
struct MatingMotion {
  Eigen::Vector3d velocity{0.0, 0.0, 0.0};          // m/s
  Eigen::Vector3d angular_velocity{0.0, 0.0, 0.0};  // rad/s
  double depth = 0.0;                               // MatingPose::depth, m
  double angle = 0.0;                               // MatingPose::angle, rad
};

// What a law carries from one tick to the next within one run (the junctions of its frictional
// contact). Plain data that the run owns and hands in; a law keeps nothing a tick changes.
struct LawState {
  FrictionState friction;
  // A second frictional contact of the same law that slips on its own coordinate (the bearing
  // face of a tightened nut beside its thread's flanks).
  FrictionState stop_friction;
};

// Stress state of the contact against the elastic limit of the parts (DIN 7190), per tick.
struct ElasticLimitCheck {
  // Largest ratio of an equivalent (von Mises) stress to the part's yield strength R_e over
  // the contact; > 1: a part yields. 0 when the law has no check or nothing is pressed.
  double utilisation = 0.0;
  int part = 0;  // where: 0 none, 1 the outer part (hub, ring), 2 the inner part (shaft, ball)
};

// Turns a contact state into the wrench the fixed part exerts on the moving part, in the mating
// frame (paper section 3.2). Force y is the axial resistance.
class FITFEEL_API ResistanceLaw {
 public:
  virtual ~ResistanceLaw();
  // Prepare-time; precomputes material and geometry constants.
  void Prepare(const PartSpec& inner, const PartSpec& outer, const ModelSettings& settings);
  // Per tick: no allocation, no locks, no exceptions, no I/O. Without history: friction is
  // the smoothed kinetic law (for probes, settling searches and the paper's traces).
  void Evaluate(const ContactState& contact, const MatingMotion& motion,
                Wrench* out) const noexcept;
  // Per tick, with the run's state: stick-slip friction where the law has it; advances `state`.
  // A law without state ignores it and gives the history-free wrench.
  void Evaluate(const ContactState& contact, const MatingMotion& motion, LawState* state,
                Wrench* out) const noexcept;
  // Per tick: the contact's stresses against the parts' elastic limits (DIN 7190).
  ElasticLimitCheck CheckElasticLimit(const ContactState& contact) const noexcept;
  // Per tick: d(radial force (x, z))/d(offset), N/m (column 0 along x, 1 along z), in closed
  // form where the law's radial force is a linear map of the contact's pressure resultant and the
  // contact carries the resultant's Jacobian (ContactState::resultant_jacobian). False, with
  // `jacobian` untouched, where the law has no such form there or the parts do not interfere.
  bool RadialJacobian(const ContactState& contact, Eigen::Matrix2d* jacobian) const noexcept;
  // Not for the tick: contact pressure per unit radial interference delta(P_ij), Pa/m, after
  // Prepare (eq. 10's coefficient), for pressure maps. UnsupportedError for a law without one.
  double PressurePerInterference() const;

 protected:
  virtual void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                         const ModelSettings& settings) = 0;
  virtual void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                          Wrench* out) const noexcept = 0;
  virtual double DoPressurePerInterference() const;
  virtual void DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                                   LawState* state, Wrench* out) const noexcept;
  virtual ElasticLimitCheck DoCheckElasticLimit(const ContactState& contact) const noexcept;
  // Default: false (no closed form).
  virtual bool DoRadialJacobian(const ContactState& contact,
                                Eigen::Matrix2d* jacobian) const noexcept;
};

}  // namespace fitfeel
