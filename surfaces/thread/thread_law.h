#pragma once

#include "framework/model/friction.h"
#include "framework/model/resistance_law.h"
#include "surfaces/thread/thread_options.h"

namespace fitfeel::thread {

// The flank law of a screw thread (docs/threads.md): a Winkler contact on the helicoid flanks,
// pressure K delta per unit interference, with Coulomb friction mu_G along the helix, against
// the screw's slip; and, where the scene tightens a joint, the bearing face's axial stop in
// series, its force the clamp's stiffness times the closure past the seat and its friction mu_K
// at the annulus's friction radius.
//
// K is chosen so that the engaged thread of the whole nut has the axial stiffness of the model's
// `contact_stiffness` (auto: VDI 2230's compliance of the engaged thread and of the nut,
// delta_G + delta_M); the stop's stiffness is the rest of the joint in series: the bolt's head,
// shank and free loaded thread and the clamped plates' deformation cone (VDI 2230). Past snug a
// turn therefore builds the preload P / (delta_S + delta_P).
class ThreadLaw final : public ResistanceLaw {
 public:
  double pressure_per_interference() const { return pressure_; }
  double clamp_stiffness() const { return clamp_stiffness_; }
  double flank_stiffness() const { return flank_stiffness_; }
  // The bearing annulus's friction radius (uniform pressure), m.
  double bearing_radius() const { return bearing_radius_; }

 protected:
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;
  void DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion, LawState* state,
                           Wrench* out) const noexcept override;
  double DoPressurePerInterference() const override { return pressure_; }
  ElasticLimitCheck DoCheckElasticLimit(const ContactState& contact) const noexcept override;
  // The normal pressure's radial stiffness, -K times the resultant's Jacobian: the radial force
  // of a part at rest. Friction along the helix has a radial share that depends on the motion,
  // which this leaves out.
  bool DoRadialJacobian(const ContactState& contact,
                        Eigen::Matrix2d* jacobian) const noexcept override;

 private:
  // The wrench with the flanks' and the face's friction given as fractions of their sliding
  // level along the screw's slip (-1 to 1: against a slip in +angle).
  void Compose(const ContactState& contact, double flank_slip, double face_slip,
               Wrench* out) const noexcept;

  double pressure_ = 0.0;         // K, Pa/m
  double flank_stiffness_ = 0.0;  // axial stiffness of the fully engaged thread, N/m
  double flank_friction_ = 0.0;   // mu_G (kinetic)
  StickSlipFriction flank_junctions_, face_junctions_;
  double pitch_radius_ = 0.0, helix_radius_ = 0.0, lead_per_radian_ = 0.0;
  double clamp_stiffness_ = 0.0;  // N/m; 0 without a joint
  double face_friction_ = 0.0;    // mu_K
  double bearing_radius_ = 0.0;
  // Elastic-limit check of the bolt (VDI 2230: von Mises of tension and the thread torque's
  // torsion over the stress cross-section); yield 0: no check.
  double stress_area_ = 0.0, polar_modulus_ = 0.0, yield_ = 0.0;
};

}  // namespace fitfeel::thread
