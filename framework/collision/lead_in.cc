#include "framework/collision/lead_in.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

// The face is drawn as a segment reaching this far beyond the lead-in's outer edge: farther than
// any device's workspace holds a part off its axis.
constexpr double kFaceHeight = 1.0;  // m
// The bore beyond the last breakpoint, as one segment this long.
constexpr double kBoreLength = 10.0;  // m
// Positions are of the order of centimetres: a point within a picometre of the boundary is on it.
constexpr double kOnBoundary = 1e-12;  // m

void CheckProfile(const RadiusProfile& profile, const char* which, bool growing) {
  if (profile.points.empty()) throw UserError(std::string("lead-in: empty ") + which + " profile");
  double u = -1.0;
  for (std::size_t i = 0; i < profile.points.size(); ++i) {
    const Eigen::Vector2d& p = profile.points[i];
    if (!p.allFinite() || !(p.y() > 0.0) || (i == 0 ? p.x() != 0.0 : !(p.x() > u))) {
      throw UserError(std::string("lead-in: the ") + which +
                      " profile needs finite points (u, radius > 0), u from 0 and increasing");
    }
    if (i > 0) {
      const double change = p.y() - profile.points[i - 1].y();
      if (growing ? change < 0.0 : change > 0.0) {
        throw UserError(std::string("lead-in: the ") + which + " part's radius must " +
                        (growing ? "not shrink behind its leading end"
                                 : "not grow behind its entrance face"));
      }
    }
    u = p.x();
  }
}

Eigen::Vector2d ClosestOnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double length_sq = ab.squaredNorm();
  if (!(length_sq > 0.0)) return a;
  const double t = (p - a).dot(ab) / length_sq;
  // The ends exactly, so that callers can tell a corner by equality.
  if (!(t > 0.0)) return a;
  if (!(t < 1.0)) return b;
  return a + t * ab;
}

}  // namespace

double RadiusProfile::At(double u) const noexcept {
  if (u <= points.front().x()) return points.front().y();
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (u <= points[i].x()) {
      const Eigen::Vector2d& a = points[i - 1];
      const Eigen::Vector2d& b = points[i];
      return a.y() + (u - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
    }
  }
  return points.back().y();
}

LeadIn::LeadIn(const RadiusProfile& moving, const RadiusProfile& fixed, double face,
               double mating_start, Section section)
    : section_(section) {
  CheckProfile(moving, "moving", true);
  CheckProfile(fixed, "fixed", false);
  if (!std::isfinite(face) || face > 0.0 || !std::isfinite(mating_start) || mating_start < 0.0) {
    throw UserError("lead-in: the entrance face must be at y <= 0 and the mating start at y >= 0");
  }
  // r_max(y) = min over s in [0, d] of fixed(d - s) - moving(s), d = y - face: the moving part's
  // section s behind its tip against the fixed part's section at the same y. Both profiles are
  // piecewise linear, so the minimum is piecewise linear in d with its kinks where d is a sum
  // of a breakpoint of each: evaluated there (at the candidate s of each), it is exact.
  std::vector<double> depths{0.0};
  for (const Eigen::Vector2d& m : moving.points) {
    for (const Eigen::Vector2d& f : fixed.points) depths.push_back(m.x() + f.x());
  }
  std::sort(depths.begin(), depths.end());
  depths.erase(std::unique(depths.begin(), depths.end()), depths.end());
  auto max_offset = [&](double d) {
    double r = fixed.At(d) - moving.At(0.0);
    auto consider = [&](double s) {
      if (s >= 0.0 && s <= d) r = std::min(r, fixed.At(d - s) - moving.At(s));
    };
    consider(d);
    for (const Eigen::Vector2d& m : moving.points) consider(m.x());
    for (const Eigen::Vector2d& f : fixed.points) consider(d - f.x());
    return r;
  };
  const double outer = max_offset(0.0);
  boundary_.emplace_back(face, outer + kFaceHeight);
  for (double d : depths) {
    const double r = max_offset(d);
    const Eigen::Vector2d point(face + d, r);
    if (r < 0.0) {
      // Wedged on the axis: the way ends where r_max crosses 0 (|offset| >= 0).
      const Eigen::Vector2d& last = boundary_.back();
      const double t = last.y() / (last.y() - r);
      boundary_.emplace_back(last.x() + t * (point.x() - last.x()), 0.0);
      break;
    }
    if (boundary_.size() > 1 && (point - boundary_.back()).norm() <= kOnBoundary) continue;
    boundary_.push_back(point);
  }
  play_ = max_offset(depths.back());
  if (play_ >= 0.0) {
    boundary_.emplace_back(boundary_.back().x() + kBoreLength, boundary_.back().y());
    capture_depth_ = std::max(mating_start, face);
  } else {
    capture_depth_ = std::min(mating_start, boundary_.back().x());
  }
}

double LeadIn::Extent(const Eigen::Vector2d& offset) const noexcept {
  switch (section_) {
    case Section::kAcrossX:
      return std::abs(offset.x());
    case Section::kSquare:
      return offset.cwiseAbs().maxCoeff();
    case Section::kRound:
      break;
  }
  return offset.norm();
}

Eigen::Vector2d LeadIn::Place(const Eigen::Vector2d& offset, double extent,
                              const Eigen::Vector2d& direction) const noexcept {
  switch (section_) {
    case Section::kAcrossX: {
      const double side = offset.x() != 0.0 ? offset.x() : direction.x();
      return {std::copysign(extent, side), offset.y()};
    }
    case Section::kSquare:
      return offset.cwiseMax(-extent).cwiseMin(extent);
    case Section::kRound:
      break;
  }
  const double r = offset.norm();
  return extent * (r > 0.0 ? Eigen::Vector2d(offset / r) : direction);
}

double LeadIn::MaxOffset(double y) const noexcept {
  // On the face's plane the part is on the face (or in front of the lead-in): free.
  if (boundary_.empty() || y <= boundary_.front().x()) {
    return std::numeric_limits<double>::infinity();
  }
  for (std::size_t i = 2; i < boundary_.size(); ++i) {
    if (y <= boundary_[i].x()) {
      const Eigen::Vector2d& a = boundary_[i - 1];
      const Eigen::Vector2d& b = boundary_[i];
      return b.x() > a.x() ? a.y() + (y - a.x()) / (b.x() - a.x()) * (b.y() - a.y()) : b.y();
    }
  }
  return play_ >= 0.0 ? play_ : -std::numeric_limits<double>::infinity();
}

bool LeadIn::Free(const Eigen::Vector2d& point) const noexcept {
  return point.y() <= MaxOffset(point.x()) + kOnBoundary;
}

Eigen::Vector2d LeadIn::Project(const Eigen::Vector2d& target,
                                const Eigen::Vector2d& previous) const noexcept {
  Eigen::Vector2d goal(target.x(), std::max(0.0, target.y()));
  if (boundary_.empty() || Free(goal)) return goal;
  const std::size_t segments = boundary_.size() - 1;
  // Where the way from the last free point first meets the boundary.
  std::size_t at = segments;
  double first = std::numeric_limits<double>::infinity();
  if (Free(previous)) {
    const Eigen::Vector2d way = goal - previous;
    for (std::size_t i = 0; i < segments; ++i) {
      const Eigen::Vector2d edge = boundary_[i + 1] - boundary_[i];
      const double cross = way.x() * edge.y() - way.y() * edge.x();
      if (cross == 0.0) continue;
      const Eigen::Vector2d rel = boundary_[i] - previous;
      const double t = (rel.x() * edge.y() - rel.y() * edge.x()) / cross;
      const double w = (rel.x() * way.y() - rel.y() * way.x()) / cross;
      if (t >= -kOnBoundary && t <= 1.0 + kOnBoundary && w >= 0.0 && w <= 1.0 && t < first) {
        first = t;
        at = i;
      }
    }
  }
  if (at == segments) {
    // No free start (a first tick inside the part, or rounding): from the boundary point
    // nearest to where the part was (to the target on a first tick, when they are one).
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < segments; ++i) {
      const double d =
          (ClosestOnSegment(boundary_[i], boundary_[i + 1], previous) - previous).norm();
      if (d < best) {
        best = d;
        at = i;
      }
    }
  }
  // Slide along the entry segment to its point nearest the goal; only where that is one of the
  // segment's ends does the part go round the corner onto the next segment, and only if that
  // brings it nearer. (Jumping to whichever segment is nearest would let a part pressed hard on
  // the face tunnel to the bore behind it.)
  auto distance = [&](std::size_t i) {
    return (ClosestOnSegment(boundary_[i], boundary_[i + 1], goal) - goal).norm();
  };
  for (std::size_t turns = 0; turns <= segments; ++turns) {
    const Eigen::Vector2d here = ClosestOnSegment(boundary_[at], boundary_[at + 1], goal);
    const double d = (here - goal).norm();
    if (at + 1 < segments && here == boundary_[at + 1] && distance(at + 1) < d) {
      ++at;
    } else if (at > 0 && here == boundary_[at] && distance(at - 1) < d) {
      --at;
    } else {
      break;
    }
  }
  Eigen::Vector2d proxy = ClosestOnSegment(boundary_[at], boundary_[at + 1], goal);
  proxy.y() = std::max(0.0, proxy.y());
  return proxy;
}

}  // namespace fitfeel
