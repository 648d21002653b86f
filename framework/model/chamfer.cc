#include "framework/model/chamfer.h"

#include <numbers>

#include "framework/core/quantity.h"

namespace fitfeel {

Chamfer ParseChamfer(const ConfigNode& node, double part_length, double wall) {
  // Any length parses (up to the 10 m no surface exceeds); the part's own limits are checked
  // below, with a message that names them.
  constexpr double kLongest = 10.0;  // m
  Chamfer chamfer;
  chamfer.angle = std::numbers::pi / 4;  // ISO 13715's plain "C" edge: 45 degrees
  if (node.is_map()) {
    node.ExpectOnlyKeys({"length", "angle"});
    chamfer.length = node.Child("length").AsQuantityIn(Dimension::kLength, 0.0, kLongest);
    if (auto angle = node.Find("angle")) {
      chamfer.angle = angle->AsQuantityIn(Dimension::kAngle, std::numbers::pi / 180,
                                          80 * std::numbers::pi / 180);
    }
  } else {
    chamfer.length = node.AsQuantityIn(Dimension::kLength, 0.0, kLongest);
  }
  // The chamfer lies on the mating end and inside the wall it cuts.
  if (chamfer.length >= part_length || chamfer.width() >= wall) {
    node.Fail("a chamfer shorter than the part (" +
                  FormatQuantity(part_length, Dimension::kLength) + ") and narrower than its wall (" +
                  FormatQuantity(wall, Dimension::kLength) + ")",
              FormatQuantity(chamfer.length, Dimension::kLength) + " long, " +
                  FormatQuantity(chamfer.width(), Dimension::kLength) + " wide");
  }
  return chamfer;
}

std::string DescribeChamfer(const Chamfer& chamfer) {
  if (!(chamfer.length > 0.0)) return {};
  return " chamfer " + FormatQuantity(chamfer.length, Dimension::kLength) + " x " +
         FormatQuantity(chamfer.width(), Dimension::kLength);
}

}  // namespace fitfeel
