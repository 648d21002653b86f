#pragma once

#include "framework/model/variation_generator.h"

namespace fitfeel::spherical {

// Draws a spherical band's radial variation V = V_dimension + V_form (+ V_surface when sampled):
// - V_dimension: one actual sphere diameter per part, D ~ U(lower, upper), V = D/2 everywhere
//   (one actual size per part, as for the other surfaces).
// - V_form on sampling sections across the band, half a form wavelength lambda ~ U(10 mm,
//   max(10 mm, B)) apart, cosine-interpolated (paper eqs. 3-5):
//   lobing in the circumference, k ~ U{2..10} lobes with per-section amplitude ~ U(0, t/2) and
//   phase ~ U(0, 2 pi), t the roundness tolerance (or the sphericity one if roundness is not
//   given): width 2 * amplitude, as the roundness oracle r = R + a cos(k theta) says;
//   meridional profile (a band that is not a sphere's zone but barrel- or waist-shaped), per
//   section ~ U(-t_s/4, t_s/4) with t_s the sphericity tolerance.
//   Step 3: evaluated with the same minimum-zone evaluations as EvaluateCharacteristics, scaled
//   down by the worst ratio while any specified characteristic exceeds its tolerance.
// - V_surface (texture: sampled): truncated Gaussian per cell on +-(A+Rz)/2, sigma = (A+Rz)/6.
// - Final clamp: two-point sizes through the centre outside the limits scale form and texture
//   together until they are inside.
class SphericalVariationGenerator final : public VariationGenerator {
 protected:
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
};

}  // namespace fitfeel::spherical
