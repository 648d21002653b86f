#include "framework/runtime/constrained_stage.h"

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
}

}  // namespace fitfeel
