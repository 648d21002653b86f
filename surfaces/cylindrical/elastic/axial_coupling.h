#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "framework/model/gps_spec.h"

namespace fitfeel::cylindrical {

// One part of a press fit as a solid of revolution: the ring between two radii, loaded by the
// interface pressure on one of its two cylindrical faces over the rows of the part's grid.
struct AxialBody {
  double inner_radius = 0.0;  // m; 0: solid
  double outer_radius = 0.0;  // m
  bool loaded_inside = true;  // the bore (a hub) is loaded, else the outside (a shaft)
  Material material;
  // Both end faces held axially (u_z = 0), the plane-strain sections' assumption, instead of free.
  bool held_faces = false;
};

// What plane sections leave out of a part's breathing (n = 0) mode: a part loaded over some of its
// rows carries the load past the loaded rows by shear and bending along its axis, so it is stiffer
// there than its Lame sections say. A shaft half a millimetre into a hub meets 4.5 times the force
// plane sections give (CalculiX, docs/contact-mechanics.md section 9): the hub's unloaded length
// and the shaft's length still outside the entrance both stiffen the loaded band.
//
// Computed, not assumed: the part's axisymmetric linear elasticity by finite elements (bilinear
// quadrilaterals in (r, z), 2 x 2 Gauss points; along the axis at least two per row and none
// longer than the loaded face's radius / 40; layers growing by 1.25 from the loaded face
// inwards), loaded by a uniform unit pressure on each row in turn. F(i, j) is row i's mean radial
// displacement under row j's pressure, positive where it opens the interface. A uniform pressure on
// every row is the Lame state, which plane sections have exactly; what the sections need is the
// rest, X = F - diag(F 1) (the diagonal removes the elements' own small error on the Lame state, so
// a uniform load shifts nothing), added to the sections' gaps. With free faces X is negative
// semidefinite: plane-stress sections are a statically admissible stress field, so by
// complementary energy the part is never softer than they say (and elements are stiffer than the
// continuum). Held faces are not that case (plane strain constrains every section): some loads
// find the part softer than its sections.
//
// The same for every circumferential order n: the load p cos(n theta) and the displacement
// u_r = U cos, u_theta = V sin, u_z = W cos (n theta) in the part's Fourier mode of order n, three
// unknowns per node. For n >= 2 plane sections are not the 3-D state of even a uniform load
// (between plane stress and plane strain), so X = F - diag(c_n) with c_n the part's own plane
// section compliance (RingHarmonicCompliance): the model's total is then the elements' F. Order 1
// carries a net force and moment, which the model's rigid offset and tilt take: body forces
// (alpha + beta z along x, per unit volume: inertia relief) balance each row's load, and the rows'
// displacement is taken relative to the line through the rows' centroids (the part's axis), as
// each section's c_1 is relative to its centroid (harmonic_compliance.h). Checked against
// CalculiX in 3-D (tools/fem/solid.py): a bent shaft in partial contact, ovality and three lobes
// growing along the axis, all within 3 % (docs/contact-mechanics.md section 6). Prepare-time only:
// it allocates.
class AxialCoupling {
 public:
  AxialCoupling() = default;
  // `row_edges`: the rows' axial boundaries (m, increasing; rows = row_edges.size() - 1).
  // `order`: the circumferential order n of the load p cos(n theta) and of the displacement the
  // matrices give (0, the breathing mode, to kHighestOrder).
  // How the elements' equations are eliminated (the same F to rounding): the whole band, or,
  // where every row has one length, the inside of equal groups of rows once for all and then the
  // station lines between them (static condensation: a 20 mm shaft in 80 rows three times faster,
  // in 400 rows eleven). kAuto takes the one with the fewer operations; kCondensed refuses rows
  // of several lengths.
  enum class Elimination { kAuto, kBand, kCondensed };
  AxialCoupling(const AxialBody& body, std::span<const double> row_edges, int order = 0,
                Elimination elimination = Elimination::kAuto);

  int order() const { return order_; }

  bool empty() const { return extra_.size() == 0; }
  int rows() const { return static_cast<int>(extra_.rows()); }
  // F: mean radial displacement of each row per unit pressure on each row, m/Pa.
  const Eigen::MatrixXd& influence() const { return influence_; }
  // X, m/Pa: F - diag(F 1) for order 0, F - diag(c_n) for the others.
  const Eigen::MatrixXd& matrix() const { return extra_; }
  // out[i] = sum_j X(i, j) mean_pressure[j] (rows() values each; Pa in, m out), for the rows
  // first .. first + count - 1 (every row without them); the others may be left as they are.
  void ExtraDisplacement(const double* mean_pressure, double* out, Eigen::Index first = 0,
                         Eigen::Index count = -1) const;

  // Rows beyond this make the influence matrix a prepare of its own (one solve per row).
  static constexpr int kMostRows = 1000;
  // Elements a fortieth of the face's radius long resolve a load's decay along the axis over
  // R / n to order 12.
  static constexpr int kHighestOrder = 12;

 private:
  int order_ = 0;
  Eigen::MatrixXd influence_, extra_;
};

}  // namespace fitfeel::cylindrical
