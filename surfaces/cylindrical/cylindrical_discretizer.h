#pragma once

#include "framework/model/discretizer.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"

namespace fitfeel::cylindrical {

// Paper step 1: m rows along the axis by n columns around it, all cells equal.
//
// Frame: the mating axis is y, rows run from y = 0 to y = l (the part's own mating length; the
// contact analyzer places the two parts along the axis). Column j has direction angle
// beta_j = 2 pi j / n in the (x, z) plane, measured from x towards z; the angles are the same for
// both parts whenever their n agree (automatic grids always do, n depending on the common nominal
// diameter only). Cell centre (R cos beta, y, R sin beta); `normal` is the radial unit vector
// (cos beta, 0, sin beta), the direction in which a positive V moves the surface for a shaft and
// for a bore alike (so centre + V * normal is the real surface point; for a bore it points into
// the material). Area pi d l / (m n) per cell.
//
// Automatic resolution (Resolution::is_auto()):
//  - rows: the shortest form wavelength (10 mm) with kSamplesPerWave = 8 samples, i.e. a pitch of
//    at most 1.25 mm: m = max(3, ceil(l / 1.25 mm)); this also exceeds the number of sampling
//    sections of any drawn form wave (one per half wave, at most 2 l / 10 mm + 1, plus the ends);
//  - columns: the highest roundness harmonic generated, K = MaxRoundnessHarmonic(d) (pi d / 10 mm,
//    clamped to 2..50 UPR), with 8 samples per wave: n = max(48, 8 K), even;
//  - texture (waviness and roughness, wavelengths below 10 mm) gets no cells: it enters the model
//    statistically.
// E.g. d = 20 mm, l = 20 mm: K = 6, 16 x 48 cells; l = 60 mm: 48 x 48.
//
// Explicit resolutions need m >= 1 and an even n >= 4 (every cell then has a diametrically
// opposite one, which two-point sizes need).
class CylindricalDiscretizer final : public Discretizer {
 public:
  static Resolution AutoResolution(const CylindricalGeometry& geometry);

 protected:
  GridShape DoShape(const PartSpec& part, const Resolution& resolution) const override;
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override;
};

// The part's geometry as a cylinder; throws UserError naming the part if it is another kind.
const CylindricalGeometry& AsCylinder(const PartSpec& part);

}  // namespace fitfeel::cylindrical
