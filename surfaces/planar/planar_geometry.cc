#include "surfaces/planar/planar_geometry.h"

#include <string>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::planar {

std::string PlanarGeometry::DoDescribe() const {
  return std::string(faces_ == 2 ? "pair of flat faces" : "square (two pairs of flat faces)") +
         " b=" + FormatQuantity(width_, Dimension::kLength) +
         " l=" + FormatQuantity(length_, Dimension::kLength) +
         " h=" + FormatQuantity(height_, Dimension::kLength) + DescribeChamfer(chamfer_);
}

std::shared_ptr<const PlanarGeometry> ParsePlanarGeometry(const PartSpec& part,
                                                          const ConfigNode& node) {
  if (!node.is_map()) node.Fail("a map {length, height, faces}", node.Describe());
  node.ExpectOnlyKeys({"length", "height", "faces", "chamfer"});
  const double width = part.size.nominal;
  // A face shorter than a micrometre or longer than 10 m is a typing error, not a part.
  const double length = node.QuantityIn("length", Dimension::kLength, 1e-6, 10.0);
  const double height = node.QuantityIn("height", Dimension::kLength, 1e-6, 10.0);
  int faces = 2;
  if (std::optional<ConfigNode> f = node.Find("faces")) {
    const long value = f->AsInteger(2, 4);
    if (value == 3) f->Fail("2 (a key's flanks) or 4 (a square)", f->Describe());
    faces = static_cast<int>(value);
  }
  // The flats of a square cannot be wider than its side.
  if (faces == 4 && height > width) {
    node.Child("height").Fail("a flat width no larger than the square's side " +
                                  FormatQuantity(width, Dimension::kLength),
                              node.Child("height").Describe());
  }
  auto parsed = std::make_shared<PlanarGeometry>(part.role, width, length, height, faces);
  if (std::optional<ConfigNode> chamfer = node.Find("chamfer")) {
    // A key's chamfer cuts at most half its width; a keyway's the hub beside it, bounded here by
    // the width too (the hub's own size is not modelled).
    parsed->set_chamfer(ParseChamfer(*chamfer, length, part.role == Role::kInner ? 0.5 * width : width));
  }
  return parsed;
}

const PlanarGeometry& PlanarGeometryOf(const PartSpec& part) {
  const auto* g = dynamic_cast<const PlanarGeometry*>(part.geometry.get());
  if (g == nullptr) throw UserError("part '" + part.name + "' has no planar geometry");
  return *g;
}

}  // namespace fitfeel::planar
