#pragma once

#include "framework/model/discretizer.h"

namespace fitfeel::conical {

// Splits a cone's lateral surface into `rows` equal axial bands by `columns` equal sectors. A cell
// carries the slant area of its band sector, pi * D(row) / n * h / cos(alpha); since D is linear
// in the axial position, the cells sum to the frustum's area exactly.
// Auto resolution: 72 columns (5 deg: lobed roundness up to 10 lobes sampled 7 times per lobe) and
// one row per 2 mm of length, at least 8 (form wavelengths are >= 10 mm by the paper, so every
// wavelength gets >= 5 samples), at most 400.
class ConicalDiscretizer final : public Discretizer {
 protected:
  GridShape DoShape(const PartSpec& part, const Resolution& resolution) const override;
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override;
};

}  // namespace fitfeel::conical
