#pragma once

#include "framework/model/discretizer.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel::planar {

// Layout of a planar grid: rows along y (the sliding direction), columns face by face, each face
// split into `columns_per_face` strips across its height. Faces are ordered +x, -x (the first
// pair) then +z, -z (the second pair of a square); the direction angle of a face's columns is the
// angle of its outward normal in the (x, z) cross-section plane: 0, pi, pi/2, 3 pi/2.
struct FaceLayout {
  int faces = 2;
  int columns_per_face = 1;
  int face_of(int column) const { return column / columns_per_face; }
  int strip_of(int column) const { return column % columns_per_face; }
  // Column of the same strip on the opposite face of the pair.
  int opposite(int column) const {
    const int f = face_of(column);
    return (f ^ 1) * columns_per_face + strip_of(column);
  }
};

// Reads the layout back from a grid (faces from its column angles); throws UserError if the grid
// is not a planar one.
FaceLayout LayoutOf(const SurfaceGrid& grid);

// Direction angle of face f's outward normal.
double FaceAngle(int face);

class PlanarDiscretizer final : public Discretizer {
 protected:
  GridShape DoShape(const PartSpec& part, const Resolution& resolution) const override;
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override;
};

}  // namespace fitfeel::planar
