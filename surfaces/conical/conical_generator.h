#pragma once

#include "framework/model/variation_generator.h"

namespace fitfeel::conical {

// Draws a cone's variation V = V_dimension + V_form (+ V_surface when sampled), radial, per cell
// (paper section 2.2 adapted to a cone):
// - V_dimension: one actual size per part, the diameter deviation D ~ U(lower, upper), V = D/2 on
//   every cell. A part has one actual size that a metrologist measures; white noise of the size
//   tolerance per cell would be a texture, not a size.
// - V_form, on sampling sections spaced half a form wavelength lambda ~ U(10 mm, max(10 mm, l))
//   apart (peaks and troughs, paper eqs. 3-5), cosine-interpolated between them:
//   axis straightness t_a: section centre offset e ~ U(0, t_a/2) at angle ~ U(0, 2 pi), giving
//     V = e cos(beta - angle) (eq. 5);
//   roundness t_r: k lobes, k ~ U{2..10}, amplitude ~ U(0, t_r/2), phase ~ U(0, 2 pi) per section;
//   generatrix straightness t_g: a common profile ~ U(-t_g/2, t_g/2) per section (barrel, waist).
//   Paper step 3: the form is evaluated with the same minimum-zone evaluations as
//   EvaluateCharacteristics and, if any specified characteristic exceeds its tolerance (the
//   components add up in some), scaled down by the worst ratio until all pass.
// - V_surface (texture: sampled): a truncated Gaussian per cell on (-(A+Rz)/2, (A+Rz)/2) with
//   sigma = (A+Rz)/6, i.e. the range is +-3 sigma (architecture notes, eq. 6).
// - Final clamp: if a two-point size leaves the size limits, form and texture are scaled together
//   (not clipped cell by cell, which would create form the spec does not allow) until all
//   two-point sizes are inside; scaled_back_cells counts the cells of the offending pairs.
// Draw order (for reproducibility): size, lambda, section offset, then per section axis, lobes,
// generatrix; lobe count; texture per cell.
class ConicalVariationGenerator final : public VariationGenerator {
 protected:
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
};

}  // namespace fitfeel::conical
