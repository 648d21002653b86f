#pragma once

#include "framework/model/gps_spec.h"
#include "surfaces/thread/thread_options.h"

namespace fitfeel::thread {

// What the thread law needs of a bolted joint (VDI 2230 Part 1, docs/threads.md), in SI.
struct JointModel {
  // delta_G + delta_M: the engaged thread's and the nut's compliance, m/N.
  double engaged_thread_compliance = 0.0;
  // The rest of the joint in series: the bolt's head, shank and free loaded thread and the
  // plates' deformation cone, 1 / (delta_SK + delta_i + delta_Gew + delta_P), N/m (0: no joint).
  double clamp_stiffness = 0.0;
  double bolt_compliance = 0.0;   // delta_S, all of the bolt's sections, m/N
  double plate_compliance = 0.0;  // delta_P, m/N
  double bearing_diameter = 0.0;  // d_W: the scene's, or the ISO 4032 nut's, m
  double hole_diameter = 0.0;     // d_h: the scene's, or the ISO 273 medium series', m
  double bearing_radius = 0.0;    // friction radius of the bearing annulus, uniform pressure, m
  double stress_area = 0.0;       // A_S, m^2
  double polar_modulus = 0.0;     // W_P of the stress cross-section, m^3
  double yield_strength = 0.0;    // R_p0.2 of the property class, Pa (0: none given)
};

// The bolt is the inner part, the nut the outer; without a joint only the engaged thread's
// compliance and the bolt's section are filled.
JointModel MakeJointModel(const PartSpec& bolt, const PartSpec& nut, const JointOptions& joint);

}  // namespace fitfeel::thread
