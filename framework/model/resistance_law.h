#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"

namespace fitfeel {

// Motion of the moving part in the fixed part's mating frame, for friction directions.
struct MatingMotion {
  Eigen::Vector3d velocity{0.0, 0.0, 0.0};          // m/s
  Eigen::Vector3d angular_velocity{0.0, 0.0, 0.0};  // rad/s
};

// Turns a contact state into the wrench the fixed part exerts on the moving part, in the mating
// frame (paper section 3.2). Force y is the axial resistance.
class FITFEEL_API ResistanceLaw {
 public:
  virtual ~ResistanceLaw();
  // Prepare-time; precomputes material and geometry constants.
  void Prepare(const PartSpec& inner, const PartSpec& outer, const ModelSettings& settings);
  // Per tick: no allocation, no locks, no exceptions, no I/O.
  void Evaluate(const ContactState& contact, const MatingMotion& motion,
                Wrench* out) const noexcept;
  // Not for the tick: contact pressure per unit radial interference delta(P_ij), Pa/m, after
  // Prepare (eq. 10's coefficient), for pressure maps. UnsupportedError for a law without one.
  double PressurePerInterference() const;

 protected:
  virtual void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                         const ModelSettings& settings) = 0;
  virtual void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                          Wrench* out) const noexcept = 0;
  virtual double DoPressurePerInterference() const;
};

}  // namespace fitfeel
