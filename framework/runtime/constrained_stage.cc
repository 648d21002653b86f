#include "framework/runtime/constrained_stage.h"

#include <cmath>
#include <limits>

#include "framework/core/error.h"
#include "framework/runtime/positioning_stage.h"

namespace fitfeel {

ConstrainedStage::ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law)
    : analyzer_(analyzer), law_(law) {
  if (!analyzer.prepared()) throw UserError("constrained stage needs a prepared contact analyzer");
}

void ConstrainedStage::DoEvaluate(const DeviceState& device, StageOutput* out) const noexcept {
  out->pose = MatingPoseOf(device);
  out->contact = ContactState{};
  analyzer_.Evaluate(out->pose, &out->contact);
  MatingMotion motion;
  motion.velocity = device.velocity;
  motion.angular_velocity = device.angular_velocity;
  out->wrench.SetZero();
  law_.Evaluate(out->contact, motion, &out->wrench);
  out->next = out->pose.depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  out->stiffness = RadialStiffness(out->pose, motion, out->wrench);
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  const ContactState& c = out->contact;
  // In clearance, S_A(gamma) - delta d is the free way outwards along the offset: where a part
  // resting against the bore (offset towards the wall it rests on) would fall to.
  if (out->stiffness == 0.0 && c.engaged && !c.interference && c.offset_distance > 0.0 &&
      c.assembly_extent >= c.offset_distance) {
    out->gap = c.assembly_extent - c.offset_distance;
    out->gap_direction = out->pose.offset / out->pose.offset.norm();
  }
}

double ConstrainedStage::RadialStiffness(const MatingPose& pose, const MatingMotion& motion,
                                         const Wrench& wrench) const noexcept {
  const Eigen::Vector2d force(wrench.force.x(), wrench.force.z());
  const double magnitude = force.norm();
  if (!(magnitude > 0.0) || !std::isfinite(magnitude)) return 0.0;
  // Forward difference one step deeper into the contact (against the force): the stiffness the
  // part meets where it is heading. 1 nm is far below every tolerance and texture height of a
  // fit (um) and far above the rounding of positions of a few mm (1e-19 m).
  constexpr double kStep = 1e-9;
  const Eigen::Vector2d into = -force / magnitude;
  MatingPose probe = pose;
  probe.offset += kStep * into;
  ContactState contact;
  analyzer_.Evaluate(probe, &contact);
  Wrench deeper;
  law_.Evaluate(contact, motion, &deeper);
  const Eigen::Vector2d deeper_force(deeper.force.x(), deeper.force.z());
  const double stiffness = (force - deeper_force).dot(into) / kStep;
  return std::isfinite(stiffness) && stiffness > 0.0 ? stiffness : 0.0;
}

}  // namespace fitfeel
