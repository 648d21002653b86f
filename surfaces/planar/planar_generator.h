#pragma once

#include "framework/model/variation_generator.h"

namespace fitfeel::planar {

// Variation of a planar part (paper section 2.2, steps 2 and 3), per pair of opposite faces:
//  - V_dimension: ONE actual size per pair, drawn uniformly in the size limits (eq. 1); each face
//    of the pair carries half of the size deviation (half-size convention of SkinModelShape).
//    A metrologist measures one width of a milled key or keyway, deviating by the cutter's wear
//    and setting, not a white noise of the tolerance's amplitude from cell to cell: that is what
//    form and texture describe.
//  - V_form per pair: a bow of the pair's median (axis straightness: + on one face, - on the
//    other) and per face a line wave along y plus a second wave scaled by the position across
//    the height (a twist / tilt across the face), so that flatness has both dimensions. Each wave
//    is eq. 3's sampled form: wavelength drawn in (10 mm, l), sampling sections at its peaks and
//    troughs with magnitudes drawn in (0, t/2), linear interpolation between them. Amplitudes:
//    the bow takes the axis straightness; the line wave the tightest of straightness, flatness and
//    parallelism given, the twist the tightest of flatness and parallelism (straightness alone:
//    the same as the line), both less the bow's.
//  - V_surface (TextureMode::kSampled only): a truncated-Gaussian draw per cell within
//    +-(A + Rz)/2 (eq. 6), sigma = (A + Rz)/6 (the band limit at 3 sigma).
//  - Step 3: the pair's form (with sampled texture) is evaluated by minimum zone against every
//    form and orientation tolerance (straightness, flatness of each face; parallelism and axis
//    straightness of the pair) and regenerated up to kMaxRegenerations times, then scaled back by
//    the worst tolerance / value (every value is homogeneous of degree one in the form).
//  - Final clamp: where V leaves the half-size limits [ei/2, es/2] (eq. 2), the pair's form and
//    texture are scaled down by the one factor that brings every cell back. Scaling, not clipping:
//    clipping would put kinks into a straight face and could break its form tolerance; scaling
//    both faces of a pair by one factor keeps every form and orientation value within tolerance.
class PlanarVariationGenerator final : public VariationGenerator {
 public:
  static constexpr int kMaxRegenerations = 8;
  // Shortest form wavelength of the paper (GPS: form above 10 mm).
  static constexpr double kMinFormWavelength = 10e-3;

 protected:
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
};

}  // namespace fitfeel::planar
