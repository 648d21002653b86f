#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel {

// What a viewer draws of one part's mating surface: one quadrilateral per cell of the part's grid
// (cell k's corners at 4k .. 4k+3, going round the cell), on the nominal surface, and the
// direction along which the cell's variation V moves it (the grid's outward normal). A viewer
// draws corner + s * V * direction with an exaggeration s of its choice, so the nominal shape
// stays true and the cells keep the piecewise-constant V the model uses.
//
// Frames as for CoarseMeshes: the inner part in the moving part's frame (its leading end at the
// origin, its axis +y, its body at y <= 0; a rotational pair: the centre at the origin), the outer
// part in the fixed part's frame (its entrance at y = 0). A viewer places the moving part at a
// MatingPose by turning it by the pose's angle about y and moving it by (offset x, depth,
// offset z); a rotational pair does not move along the axis.
struct RenderMesh {
  std::vector<Eigen::Vector3d> corners;     // 4 per cell, m
  std::vector<Eigen::Vector3d> directions;  // 1 per cell, unit
  bool empty() const { return directions.empty(); }
};

// The render mesh of a surface of revolution about y whose grid has equally spaced column angles
// (SurfaceGrid::column_angle, starting anywhere) and rows ordered along y. Row edges lie halfway
// between row centres (the end rows' outer edges mirrored); the nominal radius at an edge is
// interpolated linearly between the rows' centre radii (exact for cylinders and cones). Each grid
// point (x, y, z) goes to (x, axial_sign * y + axial_shift, z) and each normal's y component is
// multiplied by axial_sign. Throws UserError for an empty or inconsistent grid.
FITFEEL_API RenderMesh RevolutionRenderMesh(const SurfaceGrid& grid, double axial_sign,
                                            double axial_shift);

// The render mesh of a grid of flat cells (faces of a prism along y): each cell is the rectangle
// of its row's pitch along y by `cell_width` across, centred on the cell centre, in the plane
// normal to the cell's normal. Frame mapping as for RevolutionRenderMesh. Throws UserError for an
// empty grid or a non-positive width.
FITFEEL_API RenderMesh FlatCellRenderMesh(const SurfaceGrid& grid, double cell_width,
                                          double axial_sign, double axial_shift);

}  // namespace fitfeel
