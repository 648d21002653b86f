#include "surfaces/cylindrical/cylindrical_options.h"

#include <limits>
#include <string>

#include "framework/core/quantity.h"
#include "surfaces/cylindrical/elastic/axial_coupling.h"

namespace fitfeel::cylindrical {
namespace {

ElasticOptions ParseElasticOptions(const ConfigNode& options) {
  ElasticOptions o;
  if (auto node = options.Find("tilt")) {
    const std::string text = node->AsString();
    if (text == "fixed") {
      o.tilt = false;
    } else if (text != "free") {
      o.tilt_stiffness =
          node->AsQuantityIn(Dimension::kAngularStiffness, 0.0, std::numeric_limits<double>::max());
    }
  }
  if (auto node = options.Find("section")) {
    o.plane_strain = node->AsOneOf({"plane_stress", "plane_strain"}) == "plane_strain";
  }
  if (auto node = options.Find("columns")) {
    o.columns = static_cast<int>(
        node->AsInteger(ElasticOptions::kFewestColumns, ElasticOptions::kMostColumns));
    if (o.columns % 2 != 0) {
      node->Fail("an even number of columns", node->Describe());
    }
  }
  if (auto node = options.Find("axial_coupling")) o.axial_coupling = node->AsBool();
  if (auto node = options.Find("axial_orders")) {
    o.axial_orders = static_cast<int>(node->AsInteger(0, AxialCoupling::kHighestOrder));
  }
  return o;
}

}  // namespace

std::shared_ptr<const CylindricalOptions> ParseCylindricalOptions(const ConfigNode& options) {
  options.ExpectOnlyKeys(
      {"size_draw", "size_limit", "tilt", "section", "columns", "axial_coupling", "axial_orders"});
  auto parsed = std::make_shared<CylindricalOptions>();
  if (auto node = options.Find("size_draw")) {
    parsed->size_draw = node->AsOneOf({"per_part", "per_cell"}) == "per_part" ? SizeDraw::kPerPart
                                                                              : SizeDraw::kPerCell;
  }
  if (auto node = options.Find("size_limit")) {
    parsed->size_limit = node->AsOneOf({"two_point", "radial"}) == "two_point"
                             ? SizeLimit::kTwoPoint
                             : SizeLimit::kRadial;
  }
  parsed->elastic = ParseElasticOptions(options);
  return parsed;
}

}  // namespace fitfeel::cylindrical
