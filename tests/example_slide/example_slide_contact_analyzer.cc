#include "tests/example_slide/example_slide_contact_analyzer.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "tests/example_slide/example_slide_geometry.h"

namespace fitfeel::example_slide {
namespace {

// The variation every cell of `sms` shares; throws UserError if the cells differ by more than a
// picometre (a shape with form, which this analyzer cannot read).
double UniformVariation(const PartSpec& part, const SkinModelShape& sms) {
  const double v = sms.variation[0];
  if (!sms.variation.allFinite() || sms.variation.maxCoeff() - sms.variation.minCoeff() > 1e-12) {
    throw UserError("part '" + part.name +
                    "': the example slide surface models size only; its contact needs a uniform "
                    "variation");
  }
  return v;
}

}  // namespace

void SlideContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                     const PartSpec& outer, const SkinModelShape& outer_sms,
                                     const ModelSettings&) {
  if (inner.role != Role::kInner || outer.role != Role::kOuter) {
    throw UserError("slide contact needs the block (inner) first and the slot (outer) second");
  }
  clearance_ = UniformVariation(outer, outer_sms) - UniformVariation(inner, inner_sms);  // eq. 8
  block_length_ = SlideGeometryOf(inner).length();
  slot_length_ = SlideGeometryOf(outer).length();
  height_ = SlideGeometryOf(inner).height();
}

void SlideContactAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  if (!std::isfinite(pose.depth) || !pose.offset.allFinite()) return;
  const double overlap =
      std::min(pose.depth, slot_length_) - std::max(pose.depth - block_length_, 0.0);
  if (!(overlap > 0.0)) return;
  out->engaged = true;
  out->engaged_length = overlap;
  out->engaged_area = 2.0 * height_ * overlap;
  out->interference = clearance_ < 0.0;
  // Where the block may sit: the nearest point of the assembly space, or the balance position.
  const double x = pose.offset.x();
  const double anchor = clearance_ >= 0.0 ? std::clamp(x, -clearance_, clearance_) : 0.0;
  out->penetration = std::abs(x - anchor);
  if (out->penetration > 0.0) out->penetration_direction.x() = x > anchor ? 1.0 : -1.0;
  out->offset_distance = pose.offset.norm();
  out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
  out->assembly_extent = std::max(0.0, out->offset_distance - out->penetration);
  out->max_interference = std::max(0.0, -clearance_);
  out->interference_volume = out->max_interference * out->engaged_area;  // eqs. 10-11
}

}  // namespace fitfeel::example_slide
