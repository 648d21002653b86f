#pragma once

#include <memory>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::example_slide {

// A rectangular block (the inner part) sliding along y in a slot (the outer part) cut between two
// rails. Only the two flanks touch: normals +x and -x. The mating size b, the block's width and
// the slot's width, is the part's nominal size PartSpec::size.nominal.
class SlideGeometry final : public Geometry {
 public:
  SlideGeometry(double width, double length, double height, double rail_width)
      : width_(width), length_(length), height_(height), rail_width_(rail_width) {}

  double width() const { return width_; }    // b, m
  double length() const { return length_; }  // along y, m
  double height() const { return height_; }  // height of each flank in contact, m
  // Width of each rail across x (the slot's walls, compressed by a press fit), m; 0 for the block.
  double rail_width() const { return rail_width_; }

 protected:
  double DoNominalArea() const override { return 2.0 * height_ * length_; }
  double DoMatingLength() const override { return length_; }
  std::string DoDescribe() const override;

 private:
  double width_;
  double length_;
  double height_;
  double rail_width_;
};

// Parses a part's `geometry` node: {length, height} for the block, {length, height, rail_width}
// for the slot. Throws ScenarioError at the offending key (and at the part's `texture` key path
// for a part with texture, which this model refuses).
std::shared_ptr<const SlideGeometry> ParseSlideGeometry(const PartSpec& part,
                                                        const ConfigNode& node);

// The part's slide geometry; throws UserError if it has none.
const SlideGeometry& SlideGeometryOf(const PartSpec& part);

}  // namespace fitfeel::example_slide
