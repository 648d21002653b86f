#pragma once

#include <limits>
#include <string_view>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/device/device.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"

namespace fitfeel {

// Identifies the stage of an assembly (paper section 3): free positioning, then constrained mating.
enum class StageId : int { kPositioning = 0, kConstrained = 1 };

FITFEEL_API std::string_view ToString(StageId stage);

// Output of one stage tick.
struct StageOutput {
  Wrench wrench;                         // on the moving part, scene frame
  MatingPose pose;                       // where the moving part is relative to the fixed one
  ContactState contact;                  // filled by the constrained stage
  ElasticLimitCheck elastic;             // the contact's stresses against yield (constrained)
  StageId next = StageId::kPositioning;  // stage for the next tick (hand-over)
  // Radial stiffness of the contact at this pose, -dF/dx along the force (N/m); 0 when free. A
  // simulated device integrates its inertia implicitly with it, the safety chain's coupling too.
  double stiffness = 0.0;
  // Free space in front of the part when it is not in contact: the distance (m) it can move along
  // `gap_direction` (unit, in the (x, z) cross-section) before touching; infinity when unknown.
  double gap = std::numeric_limits<double>::infinity();
  Eigen::Vector2d gap_direction{0.0, 0.0};
};

// One stage of the assembly. Prepare may allocate; Evaluate is the per-tick path.
class FITFEEL_API Stage {
 public:
  virtual ~Stage();
  virtual StageId id() const = 0;
  void Evaluate(const DeviceState& device, StageOutput* out) const noexcept;

 protected:
  virtual void DoEvaluate(const DeviceState& device, StageOutput* out) const noexcept = 0;
};

}  // namespace fitfeel
