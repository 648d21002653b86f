#pragma once

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel {

// Requested grid size. Zero means "auto": the discretizer derives it from the scene (form
// wavelengths, tolerances, size) so the model holds no more cells than the scene needs.
struct Resolution {
  int rows = 0;
  int columns = 0;
  bool is_auto() const { return rows == 0 || columns == 0; }
};

// Prepare-time: splits one part's nominal mating surface into cells (paper step 1).
class FITFEEL_API Discretizer {
 public:
  virtual ~Discretizer();
  // Throws UserError if the resolution is unusable for this geometry.
  SurfaceGrid Discretize(const PartSpec& part, const Resolution& resolution) const;

 protected:
  virtual SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const = 0;
};

}  // namespace fitfeel
