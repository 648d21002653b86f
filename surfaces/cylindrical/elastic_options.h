#pragma once

namespace fitfeel::cylindrical {

// The elastic model's keys under `model.options` (law `elastic`):
//   tilt: free | fixed | <holder's angular stiffness, N*m/rad>   (default free)
//   section: plane_stress | plane_strain                          (default plane_stress)
//   columns: <most columns of the elastic solve, even, 24..1440>  (default 120)
//   axial_coupling: true | false                                  (default true)
//   axial_orders: <highest circumferential order coupled along the axes, 0..12>     (default 6)
struct ElasticOptions {
  // The grid's columns reach the elastic solve in blocks, at most this many (the grid's Fourier
  // series to the solve's highest harmonic, at the blocks' centres). Its pivoting costs
  // O(columns^3) per slice; 120 resolve harmonics to 60 (1 mm waves at d = 20 mm). A feature
  // narrower than about two solve columns lies past that (a 0.5 mm bump at d = 20 mm needs 240:
  // docs/contact-mechanics.md; docs/validation.md gives the force against the cost per `columns`).
  static constexpr int kDefaultColumns = 120;
  static constexpr int kFewestColumns = 24;
  static constexpr int kMostColumns = 1440;
  bool tilt = true;             // the moving part may tilt (4 DOF) or not (2 DOF)
  double tilt_stiffness = 0.0;  // what holds its tilt, N*m/rad (0 = nothing)
  bool plane_strain = false;
  int columns = kDefaultColumns;
  // The hub's and the shaft's deformation coupled along their axes (elastic/axial_coupling.h);
  // false leaves every section on its own (plane sections), for comparison.
  bool axial_coupling = true;
  // With the axial coupling, the orders 1 .. axial_orders are coupled too (0: the breathing mode
  // alone): order 1 is the parts' bending and shear along their axes, the others their lobing.
  // An order's coupling reaches about R / n along the axis, so high orders are local (the
  // table in docs/validation.md gives the 3-D FEM's error and the prepare's cost per setting).
  static constexpr int kDefaultAxialOrders = 6;
  int axial_orders = kDefaultAxialOrders;
};

}  // namespace fitfeel::cylindrical
