#pragma once

#include <Eigen/Core>

namespace fitfeel {

// Discretisation of one mating surface into m rows along the mating axis by n columns across it
// (around the circumference for surfaces of revolution). Cell (i, j) is stored at i * n + j.
// Coordinates are in the part's mating frame: y along the mating axis (the paper's insertion
// direction), x and z across it.
struct SurfaceGrid {
  int rows = 0;     // m
  int columns = 0;  // n
  Eigen::VectorXd row_position;     // axial coordinate of each row's centre, m (size m)
  Eigen::VectorXd column_angle;     // direction angle beta_j of each column, rad (size n)
  Eigen::Matrix3Xd centre;          // cell centres, m (3 x m*n)
  Eigen::Matrix3Xd normal;          // outward unit normals of the nominal surface (3 x m*n)
  Eigen::VectorXd area;             // cell areas, m^2 (m*n)

  int size() const { return rows * columns; }
  int index(int row, int column) const { return row * columns + column; }
};

// A skin model shape: the grid plus the variation V of each cell, the local deviation of the real
// surface from the nominal one along the direction away from the mating axis (or mid-plane):
// positive V makes a shaft fatter and a bore wider, so the local clearance is V_outer - V_inner
// (paper eq. 8). V is a radial (half-size) quantity: a diameter deviation of 8 um is V = 4 um.
// The parts of V are kept for pictures and conformance checks.
struct SkinModelShape {
  SurfaceGrid grid;
  Eigen::VectorXd variation;            // V = V_dimension + V_form (+ V_surface if sampled), m
  Eigen::VectorXd dimension_part;       // V_dimension per cell, m
  Eigen::VectorXd form_part;            // V_form per cell, m
  Eigen::VectorXd surface_part;         // V_surface per cell (zero when texture is not sampled), m
  int regenerations = 0;                // how often step 3 regenerated the form variation
  int scaled_back_cells = 0;            // cells scaled back into the size limits by the final clamp
  int rejections = 0;  // parts a statistical process scrapped (out of tolerance) before this one
};

}  // namespace fitfeel
