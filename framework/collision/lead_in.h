#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// A radius profile of a part of revolution along its axis, piecewise linear between `points`
// (u, radius) with u increasing from 0 and held at the last radius beyond the last point. For the
// moving part u is the distance behind its leading end (a chamfered end: the radius grows from
// the tip); for the fixed part the depth behind its entrance face (a chamfered entrance: the
// bore narrows from the face).
struct RadiusProfile {
  std::vector<Eigen::Vector2d> points;
  double At(double u) const noexcept;
};

// Where the leading end of an aligned moving part of revolution may be in a fixed part of
// revolution (docs/lead-in.md): in the scene frame (y the mating axis, the fixed part's mating
// surface starting at y = 0) a part whose leading end is at depth y and distance r from the axis
// touches nothing while r <= r_max(y) or while y is before the entrance face. The parts being
// round and aligned, the boundary is exact in (y, r), whatever direction the offset has: the
// moving part's outermost point in that direction is at r plus its own radius. Built once, before
// a run; Project is per tick and allocates nothing.
class FITFEEL_API LeadIn {
 public:
  // How far a part is off the axis, for its cross-section: round parts by the distance |o|; a key
  // between two flanks (normals +-x) by |o_x| alone, its height free; a square shaft by
  // max(|o_x|, |o_z|). The radius profiles are then half-widths across flats.
  enum class Section { kRound, kAcrossX, kSquare };

  // No lead-in: every pose is free.
  LeadIn() = default;
  // `moving` and `fixed` as RadiusProfile says; `face` is the y of the fixed part's entrance face
  // (<= 0: a chamfer lies in front of the mating surface) and `mating_start` the y at which the
  // moving part's leading end has its whole mating surface's radius inside the fixed part's
  // mating surface (the end of the moving part's chamfer, >= 0). Throws UserError for a profile
  // that is empty, not finite, not increasing in u, a moving radius that shrinks behind the tip
  // or a fixed one that grows behind the face.
  LeadIn(const RadiusProfile& moving, const RadiusProfile& fixed, double face,
         double mating_start, Section section = Section::kRound);

  Section section() const { return section_; }
  // The offset's distance from the axis in the section's measure (see Section).
  double Extent(const Eigen::Vector2d& offset) const noexcept;
  // `offset` brought to extent `extent` (<= its own) as the section constrains it: a round part
  // along its direction (`direction`, a unit vector, where the offset is zero), a key across the
  // flanks only, a square per axis.
  Eigen::Vector2d Place(const Eigen::Vector2d& offset, double extent,
                        const Eigen::Vector2d& direction) const noexcept;

  bool empty() const { return boundary_.empty(); }
  // r_max at depth y (+infinity before the face).
  double MaxOffset(double y) const noexcept;
  // The radial play left once the parts' mating surfaces overlap: r_max far inside (negative for
  // an interference fit).
  double play() const { return play_; }
  // Where the constrained stage takes over: the moving part's mating surface has entered the
  // fixed one's (mating_start), or, for an interference fit, the first depth at which the parts
  // wedge on the axis (r_max = 0), whichever comes first. The constrained stage's depth is
  // measured from here.
  double capture_depth() const { return capture_depth_; }
  // The boundary in (y, r), from the face's outer end down the lead-in to the mating surface.
  const std::vector<Eigen::Vector2d>& boundary() const { return boundary_; }

  // The god object (Zilles & Salisbury 1995) in (y, r): where the part is, given where the device
  // holds it (`target`) and where it was on the last tick (`previous`, a free point). A target
  // in free space is the answer. Otherwise the part stays on the surface: it enters the boundary
  // where the straight way from `previous` to `target` first meets it and slides from there
  // along the boundary to the nearest point to the target it can reach without passing a point
  // that is farther (a local, not global, closest point: a part pressed on the face does not
  // tunnel to the bore behind it). r is >= 0.
  Eigen::Vector2d Project(const Eigen::Vector2d& target, const Eigen::Vector2d& previous) const
      noexcept;
  bool Free(const Eigen::Vector2d& point) const noexcept;

 private:
  std::vector<Eigen::Vector2d> boundary_;  // (y, r), y nondecreasing, r nonincreasing
  Section section_ = Section::kRound;
  double play_ = 0.0;
  double capture_depth_ = 0.0;
};

}  // namespace fitfeel
