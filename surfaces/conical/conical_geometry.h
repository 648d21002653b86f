#pragma once

#include <memory>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/chamfer.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::conical {

// Nominal geometry of one conical mating surface: a taper pin (inner) or a taper-reamed hole
// (outer) of taper ratio C = 2 tan(alpha) (1:50 for ISO 2339 pins). The mating size is the
// nominal small-end diameter d (PartSpec::size.nominal), as ISO 2339 specifies the pin.
//
// Axial coordinates (SurfaceGrid::row_position) run from the end that leads into the joint:
//   pin:  t in [0, length] from its small end, diameter d + C t;
//   hole: y in [0, length] from its entrance (its large end), diameter d + C (length - y).
class ConicalGeometry final : public Geometry {
 public:
  ConicalGeometry(Role role, double small_diameter, double length, double taper,
                  double outer_diameter);

  Role role() const { return role_; }
  double small_diameter() const { return small_diameter_; }  // d, m
  double large_diameter() const { return small_diameter_ + taper_ * length_; }
  double length() const { return length_; }                  // m
  double taper() const { return taper_; }                    // C = 2 tan(alpha)
  double half_angle() const { return half_angle_; }          // alpha, rad
  double outer_diameter() const { return outer_diameter_; }  // hole: hub outer diameter d2, m
  // Nominal diameter at an axial coordinate of this part (see above), m.
  double DiameterAt(double axial) const;
  // Mean diameter over the length, m.
  double mean_diameter() const { return small_diameter_ + 0.5 * taper_ * length_; }
  // The lead-in chamfer at the mating end (the pin's small end, the hole's entrance), in front
  // of the mating cone (docs/lead-in.md); zero length: a sharp edge.
  const Chamfer& chamfer() const { return chamfer_; }
  void set_chamfer(const Chamfer& chamfer) { chamfer_ = chamfer; }

 protected:
  double DoNominalArea() const override;
  double DoMatingLength() const override { return length_; }
  std::string DoDescribe() const override;

 private:
  Role role_;
  double small_diameter_;
  double length_;
  double taper_;
  double half_angle_;
  double outer_diameter_;
  Chamfer chamfer_;
};

// Parses a part's `geometry` node: {length, taper} for the pin, {length, taper, outer_diameter}
// for the hole, each with an optional `chamfer` at its mating end (ParseChamfer). `taper` is
// "1:50" or the ratio C as a number.
std::shared_ptr<const ConicalGeometry> ParseConicalGeometry(const PartSpec& part,
                                                            const ConfigNode& node);

// The part's conical geometry; throws UserError if the part has another kind.
const ConicalGeometry& GeometryOf(const PartSpec& part);

}  // namespace fitfeel::conical
