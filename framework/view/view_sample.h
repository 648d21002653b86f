#pragma once

#include <cstdint>

#include "framework/runtime/tick_record.h"

namespace fitfeel::view {

// The part of a tick's record a viewer shows, as plain numbers (trivially copyable, so that it can
// cross threads through SpscRing). SI units, in the outer part's mating frame, which the viewer
// draws fixed: the inner part's pose in it and what acts on the inner part. That is the scene's
// frame (TickRecord) where the inner part moves; where the outer part moves, the scene's reflected
// in z (InOuterPartsFrame, AnalyzerPose).
struct ViewSample {
  double time = 0.0;  // s
  std::uint64_t tick = 0;
  double depth = 0.0;                     // m
  double offset_x = 0.0, offset_z = 0.0;  // m
  double angle = 0.0;                     // rad
  double force[3] = {0.0, 0.0, 0.0};      // N, on the moving part
  double torque[3] = {0.0, 0.0, 0.0};     // N*m
  double offset_distance = 0.0;           // m
  double offset_angle = 0.0;              // rad
  double assembly_extent = 0.0;           // m
  double penetration = 0.0;               // m
  double max_interference = 0.0;          // m
  std::uint8_t stage = 0;                 // StageId
  bool engaged = false;
  bool interference = false;
  bool guard_fault = false;
};

// A sample taken in the scene frame, brought into the outer part's (the view's) for the scene's
// `moving` part: the reflection in z of its offset, its force and torque and its offset angle
// where the outer part moves (AnalyzerPose), nothing otherwise.
inline void InOuterPartsFrame(ViewSample* s, Role moving) noexcept {
  if (moving != Role::kOuter) return;
  s->offset_z = -s->offset_z;
  s->force[2] = -s->force[2];
  s->torque[2] = -s->torque[2];
  s->offset_angle = -s->offset_angle;
}

// Copies what a viewer shows out of a tick's record (in the scene frame), in the outer part's
// frame for the scene's `moving` part. No allocation: called in the tick.
inline ViewSample MakeViewSample(const TickRecord& r, std::uint64_t tick,
                                 Role moving = Role::kInner) noexcept {
  ViewSample s;
  s.time = r.time;
  s.tick = tick;
  s.depth = r.pose.depth;
  s.offset_x = r.pose.offset.x();
  s.offset_z = r.pose.offset.y();
  s.angle = r.pose.angle;
  for (int i = 0; i < 3; ++i) {
    s.force[i] = r.wrench.force[i];
    s.torque[i] = r.wrench.torque[i];
  }
  s.offset_distance = r.contact.offset_distance;
  s.offset_angle = r.contact.offset_angle;
  s.assembly_extent = r.contact.assembly_extent;
  s.penetration = r.contact.penetration;
  s.max_interference = r.contact.max_interference;
  s.stage = static_cast<std::uint8_t>(r.stage);
  s.engaged = r.contact.engaged;
  s.interference = r.contact.interference;
  s.guard_fault = r.guard_fault;
  InOuterPartsFrame(&s, moving);
  return s;
}

}  // namespace fitfeel::view
