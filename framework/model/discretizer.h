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

// Grid dimensions a resolution gives on a part, known before any cell exists.
struct GridShape {
  int rows = 0;
  int columns = 0;
  long cells() const { return static_cast<long>(rows) * columns; }
};

// Prepare-time: splits one part's nominal mating surface into cells (paper step 1).
class FITFEEL_API Discretizer {
 public:
  virtual ~Discretizer();
  // The grid `resolution` gives on `part` (auto resolved), without building it: the scenario
  // loader calls it so that `validate` refuses what Discretize would, and the cost estimate
  // counts cells. Throws UserError if the resolution is unusable for this geometry.
  GridShape Shape(const PartSpec& part, const Resolution& resolution) const;
  // Checks through Shape first: one path for the refusals. Throws UserError.
  SurfaceGrid Discretize(const PartSpec& part, const Resolution& resolution) const;

 protected:
  // Default: the resolution as given (an auto one is unknown: zeros), no constraint of its own.
  virtual GridShape DoShape(const PartSpec& part, const Resolution& resolution) const;
  virtual SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const = 0;
};

}  // namespace fitfeel
