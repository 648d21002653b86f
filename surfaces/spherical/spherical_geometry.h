#pragma once

#include <memory>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::spherical {

// Nominal geometry of one spherical mating surface: the ball (inner ring of a spherical plain
// bearing, inner) or the socket (outer ring, outer). The mating size is the sphere diameter dk
// (PartSpec::size.nominal). Only a band of the sphere is real: the zone of width `width` symmetric
// about the equator, the plane through the centre normal to the bearing axis y. Axial coordinates
// (SurfaceGrid::row_position) are y in [-width/2, width/2], from the centre.
class SphericalGeometry final : public Geometry {
 public:
  SphericalGeometry(Role role, double diameter, double width, double outer_diameter,
                    double bore_diameter = 0.0)
      : role_(role),
        diameter_(diameter),
        width_(width),
        outer_diameter_(outer_diameter),
        bore_diameter_(bore_diameter) {}

  Role role() const { return role_; }
  double diameter() const { return diameter_; }              // dk, m
  double radius() const { return 0.5 * diameter_; }          // a, m
  double width() const { return width_; }                    // band width B, m
  double outer_diameter() const { return outer_diameter_; }  // socket: outer ring diameter D, m
  double bore_diameter() const { return bore_diameter_; }    // ball: inner ring bore d, 0 solid
  // Mean distance of the band from the bearing axis, uniform in y (the band's area is uniform in
  // y, 2 pi a dy): (1/B) * integral of sqrt(a^2 - y^2) over [-B/2, B/2], m.
  double mean_axis_distance() const;

 protected:
  // A zone of a sphere has area 2 pi a * height (Archimedes): 2 pi a B.
  double DoNominalArea() const override;
  double DoMatingLength() const override { return width_; }
  std::string DoDescribe() const override;

 private:
  Role role_;
  double diameter_;
  double width_;
  double outer_diameter_;
  double bore_diameter_;
};

// Parses a part's `geometry` node: {width, bore_diameter (optional)} for the ball, {width,
// outer_diameter} for the socket.
std::shared_ptr<const SphericalGeometry> ParseSphericalGeometry(const PartSpec& part,
                                                                const ConfigNode& node);

// The part's spherical geometry; throws UserError if the part has another kind.
const SphericalGeometry& GeometryOf(const PartSpec& part);

}  // namespace fitfeel::spherical
