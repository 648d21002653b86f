#pragma once

#include "framework/model/discretizer.h"

namespace fitfeel::spherical {

// Splits the band |y| <= B/2 of a sphere of radius a into `rows` slices of equal height h = B/m
// by `columns` equal sectors. Every cell of a zone of height h has area 2 pi a h / n (Archimedes),
// so the cells are equal and sum to 2 pi a B exactly. Cell centres sit at latitude asin(y/a) of
// the row's mid height; normals point away from the centre.
// Auto resolution: 72 columns (5 deg) and one row per mm of band width, at least 8, at most 400.
class SphericalDiscretizer final : public Discretizer {
 protected:
  GridShape DoShape(const PartSpec& part, const Resolution& resolution) const override;
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override;
};

}  // namespace fitfeel::spherical
