#pragma once

#include <vector>

#include "framework/model/discretizer.h"
#include "framework/model/surface_type.h"
#include "framework/model/variation_generator.h"

namespace fitfeel::example_slide {

// Grid of the two flanks: rows along y from the part's trailing end (row_position from 0 to the
// length), columns flank by flank (+x first, then -x), each flank in strips across its height.
// column_angle is the flank normal's angle in the (x, z) plane: 0 and pi.
class SlideDiscretizer final : public Discretizer {
 public:
  // The variation is uniform, so one cell per flank would carry the model; 5 mm rows only make
  // pictures readable.
  static constexpr double kAutoRowLength = 5e-3;

 protected:
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override;
};

// Size only: one actual size per part, uniform in its limits (a measured width, not cell-to-cell
// noise); each flank carries half of its deviation, since V is a half-size quantity. No form and
// no texture (the surface type offers no form characteristic and refuses texture).
class SlideVariationGenerator final : public VariationGenerator {
 protected:
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
};

// Two-point sizes (ISO 14405-1 default): b + V(+x cell) + V(facing -x cell), smallest and largest,
// against the size limits.
std::vector<CharacteristicCheck> EvaluateSlideCharacteristics(const PartSpec& part,
                                                              const SkinModelShape& sms);

}  // namespace fitfeel::example_slide
