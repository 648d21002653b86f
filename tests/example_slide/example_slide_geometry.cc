#include "tests/example_slide/example_slide_geometry.h"

#include <string>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::example_slide {

std::string SlideGeometry::DoDescribe() const {
  std::string text = std::string(rail_width_ > 0.0 ? "slot" : "block") +
                     " b=" + FormatQuantity(width_, Dimension::kLength) +
                     " l=" + FormatQuantity(length_, Dimension::kLength) +
                     " h=" + FormatQuantity(height_, Dimension::kLength);
  if (rail_width_ > 0.0) text += " rails " + FormatQuantity(rail_width_, Dimension::kLength);
  return text;
}

std::shared_ptr<const SlideGeometry> ParseSlideGeometry(const PartSpec& part,
                                                        const ConfigNode& node) {
  const bool slot = part.role == Role::kOuter;
  if (!node.is_map()) {
    node.Fail(slot ? "a map {length, height, rail_width}" : "a map {length, height}",
              node.Describe());
  }
  if (slot) {
    node.ExpectOnlyKeys({"length", "height", "rail_width"});
  } else {
    node.ExpectOnlyKeys({"length", "height"});
  }
  // Shorter than a micrometre or longer than 10 m is a typing error, not a part.
  const double length = node.QuantityIn("length", Dimension::kLength, 1e-6, 10.0);
  const double height = node.QuantityIn("height", Dimension::kLength, 1e-6, 10.0);
  const double rail_width =
      slot ? node.QuantityIn("rail_width", Dimension::kLength, 1e-6, 10.0) : 0.0;
  // The model has no texture term: refuse it rather than ignore it. The part's `texture` node is
  // not at hand here, so the error names its key path in the same file.
  if (part.texture.waviness > 0.0 || part.texture.ra > 0.0 || part.texture.rz > 0.0) {
    const std::string parent = node.path().substr(0, node.path().rfind('.') + 1);
    throw ScenarioError({node.file(), 0, 0}, parent + "texture",
                        "no texture (the example slide surface models size only)",
                        "a texture on part '" + part.name + "'");
  }
  return std::make_shared<SlideGeometry>(part.size.nominal, length, height, rail_width);
}

const SlideGeometry& SlideGeometryOf(const PartSpec& part) {
  const auto* g = dynamic_cast<const SlideGeometry*>(part.geometry.get());
  if (g == nullptr) throw UserError("part '" + part.name + "' has no slide geometry");
  return *g;
}

}  // namespace fitfeel::example_slide
