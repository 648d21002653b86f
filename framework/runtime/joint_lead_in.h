#pragma once

#include <Eigen/Core>

#include "framework/collision/lead_in.h"
#include "framework/core/export.h"

namespace fitfeel {

// What a feature's lead-in (its chamfers and its fixed part's entrance face, LeadIn) does to the
// moving part of a joint before that feature's surfaces overlap: the feature's moving part meets
// the lead-in at depth y (the lead-in's y: the feature's depth plus the lead-in's capture depth)
// with its offset across the axis (the feature's frame).
struct LeadInPush {
  double axial = 0.0;                  // N along +y, on the moving part
  Eigen::Vector2d across{0.0, 0.0};    // N in the (x, z) cross-section, on the moving part
  bool touching = false;
};

// A penalty of stiffness `stiffness` (N/m) on the lead-in's boundary: free inside it; on a
// chamfer, the overlap across the axis at y taken along the chamfer's normal (so that the chamfer
// turns part of an axial push into a push across the axis that brings the part into line, as the
// one-feature lead-in's god object slides a part down it); beyond the chamfer's outer edge, on
// the entrance face, an axial push back out of the face (an end meeting a face guides nothing
// across). Convex in the offset at a given depth on the chamfer, constant in it on the face, so a
// balance across the axis sees only the chamfers. Per tick: allocates nothing.
FITFEEL_API LeadInPush PushOfLeadIn(const LeadIn& lead_in, double y, const Eigen::Vector2d& offset,
                                    double stiffness) noexcept;

}  // namespace fitfeel
