#pragma once

#include "framework/model/variation_generator.h"
#include "surfaces/cylindrical/cylindrical_options.h"

namespace fitfeel::cylindrical {

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
  // Takes size_draw and size_limit from the scene's CylindricalOptions.
  void DoConfigure(const SurfaceOptions& options) override;
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
  bool DoSupports(ProcessKind) const override { return true; }

 private:
  GeneratorOptions options_;
};

}  // namespace fitfeel::cylindrical
