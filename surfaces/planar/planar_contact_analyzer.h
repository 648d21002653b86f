#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"
#include "framework/model/texture_contact.h"
#include "surfaces/planar/planar_discretizer.h"

namespace fitfeel::planar {

// Contact and space analysis of the inner part (key, square shaft) sliding along +y between the
// outer part's faces (keyway walls, square hole), paper section 3.1 in the planar case.
//
// Alignment as in the cylindrical analyzer: depth D = 0 puts the inner part's leading end (its
// largest y) at the outer part's entrance (its smallest y); an inner point at distance s behind
// its leading end sits D - s into the outer part. The overlap is cut into slices at every row
// boundary of either part, so each slice faces one inner row and one outer row.
//
// Tolerance space (eq. 8): S_T = V_outer - V_inner per slice and column (cells face each other:
// same face, same strip across the height). A lateral offset p = (x, z) of the inner part closes
// the gaps of the faces whose normal u points along p: gap = S_T - p . u. Because the normals are
// +-x and +-z only, the assembly space is the rectangle (an interval for a key)
//   max_(-x) (-S_T) <= x <= min_(+x) S_T,   max_(-z) (-S_T) <= z <= min_(+z) S_T
// over the overlapping slices. An axis whose interval is empty interferes (paper 3.2.2): the
// part sits where the elastic energy sum(area * delta^2) of a Winkler bed is least, i.e. where the
// two faces' summed interference forces balance (one monotone equation per axis, solved by
// bisection to 1e-3 of a picometre). A key has one pair: z is free (no face constrains it).
//
// Tables per depth step (prepare): per axis the interval, the interference flag and the balance
// position; the engaged length and area; the interference volume sum(area * delta), its largest
// delta and resultant, at the balance position under interference and at the middle of the
// interval otherwise. delta is the sharp max(0, -gap), or with TextureMode::kExpected the expected
// interference E[(X - gap)+] of the equivalent rough-on-smooth texture (texture_contact.h), which
// is not zero inside the interval when the texture's band reaches across the gap.
//
// Per tick: linear interpolation between the two neighbouring steps of every scalar and of the
// anchor (the nearest point of the interval, or the balance position), as in the cylindrical
// analyzer, so forces are continuous in depth and offset. O(1), no allocation.
//
// ContactState's radial fields in the planar reading: offset_distance = |p|; penetration = the
// distance from p to the anchor; penetration_direction = (p - anchor) / penetration (the radial
// spring pushes back along minus it) and offset_angle its angle; assembly_extent =
// offset_distance - penetration, clamped at 0.
class PlanarContactAnalyzer final : public ContactAnalyzer {
 public:
  int depth_steps() const { return static_cast<int>(depth_.size()); }
  double depth_step() const { return step_; }
  double max_depth() const { return max_depth_; }
  // Tabulated interval of axis a (0: x, 1: z) at step k; lower > upper means interference.
  double lower(int k, int axis) const { return lower_[Index(k, axis)]; }
  double upper(int k, int axis) const { return upper_[Index(k, axis)]; }
  double balance(int k, int axis) const { return balance_[Index(k, axis)]; }

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override;
  // The rectangle of the nearer depth step (empty under interference or before engagement). A
  // key's z is free: the rectangle is drawn as high as its x interval is wide around z = 0.
  bool DoAssemblySpace(const MatingPose& pose,
                       std::vector<Eigen::Vector2d>* polygon) const override;

 private:
  struct Slice {
    int inner_row;
    int outer_row;
    double length;
  };
  static std::size_t Index(int k, int axis) { return 2 * static_cast<std::size_t>(k) + axis; }
  void SlicesAt(double depth, std::vector<Slice>* slices) const;
  bool Locate(double depth, std::size_t* k, double* t) const noexcept;
  // Where the spring of eq. 9 pulls coordinate `x` of `axis` at step k, with each face's interval
  // narrowed by `twist_reach` on both sides (a twisted part's face edges reach that much further).
  double AnchorAt(std::size_t k, int axis, double x, double twist_reach) const noexcept;

  FaceLayout layout_;
  int axes_ = 1;
  // Half the faces' contact height: a twist theta about the mating axis moves a face's edges
  // across it by half_height_ * theta (a square's flats, a key's flank in its keyway).
  double half_height_ = 0.0;
  std::vector<double> inner_edges_, outer_edges_;
  double inner_length_ = 0.0, outer_length_ = 0.0;
  double min_overlap_ = 0.0;  // slices shorter than this are rounding slivers, m
  Eigen::VectorXd v_inner_, v_outer_, inner_area_;
  ExpectedInterferenceTable texture_;

  double step_ = 0.0, max_depth_ = 0.0;
  std::vector<double> depth_, length_, area_, volume_, max_delta_;
  std::vector<Eigen::Vector2d> resultant_;
  std::vector<char> engaged_;
  std::vector<double> lower_, upper_, balance_;  // per step and axis
  std::vector<char> empty_;                      // per step and axis
};

}  // namespace fitfeel::planar
