#pragma once

#include <memory>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/chamfer.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::planar {

// Nominal geometry of one planar mating surface: pairs of opposite flat faces that slide along the
// mating axis y. A parallel key in its keyway has one pair (the flanks, normals +-x); a square
// shaft in its square hole has two (normals +-x and +-z). The mating size (key width, keyway
// width, side of the square) is the part's nominal size PartSpec::size.nominal.
class PlanarGeometry final : public Geometry {
 public:
  PlanarGeometry(Role role, double width, double length, double height, int faces)
      : role_(role), width_(width), length_(length), height_(height), faces_(faces) {}

  Role role() const { return role_; }
  double width() const { return width_; }    // nominal distance between opposite faces b, m
  double length() const { return length_; }  // length of each face along y, m
  // Height of each face in contact, across the sliding direction (a key's flank height engaged in
  // this keyway; a square's flat width), m.
  double height() const { return height_; }
  int faces() const { return faces_; }  // 2 (one pair) or 4 (two pairs)
  int pairs() const { return faces_ / 2; }
  // The lead-in chamfer on the faces' mating edges (a key's leading end, a keyway's entrance),
  // in front of the mating faces (docs/lead-in.md); zero length: sharp edges.
  const Chamfer& chamfer() const { return chamfer_; }
  void set_chamfer(const Chamfer& chamfer) { chamfer_ = chamfer; }

 protected:
  double DoNominalArea() const override { return faces_ * height_ * length_; }
  double DoMatingLength() const override { return length_; }
  std::string DoDescribe() const override;

 private:
  Role role_;
  double width_;
  double length_;
  double height_;
  int faces_;
  Chamfer chamfer_;
};

// Parses a part's `geometry` node: {length, height, faces (2 | 4, default 2), chamfer (optional,
// ParseChamfer)}. Throws
// ScenarioError at the offending key.
std::shared_ptr<const PlanarGeometry> ParsePlanarGeometry(const PartSpec& part,
                                                          const ConfigNode& node);

// The part's planar geometry; throws UserError if it has none.
const PlanarGeometry& PlanarGeometryOf(const PartSpec& part);

}  // namespace fitfeel::planar
