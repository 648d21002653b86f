#pragma once

#include <limits>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/runtime/contact_search.h"

namespace fitfeel {

// What the god object's balance across the axis at one depth carries from tick to tick.
struct AcrossMemory {
  // On a Winkler bed (the cone's, the sphere's): the last balance's slope (the wall's
  // stiffness plus the spring's, N/m; 0 = not known yet) and where it lay from the device (m;
  // NaN = not known yet); the next tick's search starts around that root.
  double across_slope = 0.0;
  double across_root = std::numeric_limits<double>::quiet_NaN();
  // The same for the step back out of the wall along the push (where the push exceeds the
  // pull).
  double back_slope = 0.0;
  double back_root = std::numeric_limits<double>::quiet_NaN();
  // On a Winkler bed whose stiffness comes in closed form (ResistanceLaw::RadialJacobian):
  // where the last balance left the part (NaN = not known, or free), the next one's start.
  Eigen::Vector2d bed_part{std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::quiet_NaN()};
  // On an assembly space's edge: the slope of the last balance on the line from the edge to
  // the device (the wall's stiffness along it plus the spring's, N/m; 0 = not known yet).
  double line_slope = 0.0;
};

// What the god object carries from tick to tick (in the run's state).
struct GodObjectMemory {
  // The part's offset and mating depth: where the god object left it.
  Eigen::Vector2d part{0.0, 0.0};
  double part_depth = 0.0;
  // The balances across the axis: at the device's depth, and at the part's own where it lags the
  // device (a jammed part: both are solved every tick, each from its own memory; one shared
  // memory warm-started each from the other's root took 10-12 evaluations each).
  AcrossMemory at_device;
  AcrossMemory at_part;
  bool lagged = false;  // the last tick solved the balance at the part's own depth
};

// The constrained stage's god object: a part coupled to the device across the axis by a spring
// (a hand at a haptic device renders no stiffer than that), placed where the contact's push
// balances the spring across the axis and the law's resistance balances it along the axis. Reads
// the prepared analyzer and law only; what it carries between ticks is the run's GodObjectMemory.
class FITFEEL_API GodObject {
 public:
  // `search` must outlive the god object; `stiffness` (N/m, finite and > 0) is the spring's.
  GodObject(const ContactSearch& search, double stiffness)
      : search_(search), stiffness_(stiffness) {}

  // Moves the part from where it was (in `*memory`) towards the device's pose (out->pose on
  // entry) until the contact's push balances the spring across the axis, and the law's
  // resistance (with the run's `*law_state`) balances it along the axis; leaves the outputs at
  // the part's pose with the spring's wrench on the device.
  void FollowDevice(const MatingMotion& device_motion, GodObjectMemory* memory,
                    LawState* law_state, StageOutput* out) const noexcept;

 private:
  const ContactSearch& search_;
  double stiffness_;
};

}  // namespace fitfeel
