#pragma once

#include "framework/model/contact_analyzer.h"

namespace fitfeel::example_slide {

// Contact of the block sliding along +y in the slot (paper section 3.1 for two flat flanks).
//
// Depth 0 puts the block's leading end at the slot's entrance; at depth d the block spans
// [d - l_block, d] of the slot's [0, l_slot], and the overlap is the engaged length.
// Tolerance space (eq. 8): S_T = V_slot - V_block, the same on every facing pair of cells since
// both variations are uniform. A lateral offset x closes one flank's gap by |x|, so the assembly
// space is |x| <= S_T (z is free: no flank faces it). S_T < 0 is interference: the block sits at
// x = 0, where the two flanks' forces balance, with delta = -S_T on every engaged cell.
//
// Prepare reduces both shapes to S_T and the lengths, so Evaluate is a few arithmetic operations
// (a surface with form would tabulate per depth step here, see surfaces/planar). ContactState in
// this reading: penetration = distance of x from the assembly space (or from 0 under interference)
// along +-x; interference_volume = delta * engaged area at the balance position.
class SlideContactAnalyzer final : public ContactAnalyzer {
 public:
  double clearance() const { return clearance_; }  // S_T per flank, m (negative: interference)

 protected:
  // Throws UserError for a shape whose variation is not uniform (this model has no form).
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;

 private:
  double clearance_ = 0.0;
  double block_length_ = 0.0;
  double slot_length_ = 0.0;
  double height_ = 0.0;
};

}  // namespace fitfeel::example_slide
