#pragma once

#include "framework/model/variation_generator.h"

namespace fitfeel::cylindrical {

// How the dimensional variation is drawn (paper eq. 1 "rand(t_min, t_max)"), model.options key
// `size_draw`.
enum class SizeDraw {
  // per_part (default): one actual size per part, as a workpiece has, plus the local variation
  // of its form. The size is drawn uniformly among the sizes that keep every local size within
  // the limits given the part's form (the form's own two-point spread narrows the range the mean
  // size can take); when the form alone spreads wider than the tolerance, it is scaled back.
  kPerPart,
  // per_cell: the literal reading of eq. 1 per discrete point: white noise of the size
  // tolerance's amplitude. Its SMS meets the size limits but not, in general, form tolerances
  // tighter than the size tolerance (the noise itself is form error).
  kPerCell,
};

// Which size limits the final clamp (paper step 3) enforces, model.options key `size_limit`.
enum class SizeLimit {
  // two_point (default): every two-point size (ISO 14405-1 LP, opposite cells) within the limits.
  // The axis may bend and odd lobes may grow, as on a real part, without changing local sizes.
  kTwoPoint,
  // radial: eq. 2 read literally with V radial, lower/2 <= V <= upper/2 at every cell: the
  // surface stays between two coaxial cylinders at the limits around the nominal axis (stricter
  // than two-point sizes and than the envelope requirement).
  kRadial,
};

struct GeneratorOptions {
  SizeDraw size_draw = SizeDraw::kPerPart;
  SizeLimit size_limit = SizeLimit::kTwoPoint;
  // Paper step 3: a form component whose accumulated result fails a specified form check is
  // regenerated up to this many times, then scaled back (bisection) as the last resort.
  int max_regenerations = 10;
};

// Paper section 2.2, steps 2 and 3, for a cylindrical surface. See README.md for the model.
class CylindricalVariationGenerator final : public VariationGenerator {
 public:
  CylindricalVariationGenerator() = default;
  explicit CylindricalVariationGenerator(GeneratorOptions options) : options_(options) {}
  const GeneratorOptions& options() const { return options_; }

 protected:
  void DoConfigure(const ConfigNode& options) override;
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
  bool DoSupports(ProcessKind) const override { return true; }

 private:
  GeneratorOptions options_;
};

}  // namespace fitfeel::cylindrical
