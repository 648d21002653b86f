#include "surfaces/cylindrical/cylindrical_surface.h"

#include <cmath>
#include <string>

#include "framework/core/quantity.h"
#include "framework/metrology/sms_conformance.h"
#include "surfaces/cylindrical/contact_factory.h"
#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"
#include "surfaces/cylindrical/cylindrical_variation_generator.h"

namespace fitfeel::cylindrical {
namespace {
// Longest mating surface or largest diameter accepted: 10 m, well past any part a haptic
// device assembles, but it keeps typos like "20 m" for "20 mm" from making a billion cells.
constexpr double kMaxSize = 10.0;
}  // namespace

std::vector<FormCharacteristic> CylindricalSurface::form_characteristics() const {
  return {FormCharacteristic::kAxisStraightness, FormCharacteristic::kGeneratrixStraightness,
          FormCharacteristic::kRoundness, FormCharacteristic::kCylindricity};
}

std::vector<std::string> CylindricalSurface::law_names() const { return LawNames(); }

std::unique_ptr<Discretizer> CylindricalSurface::MakeDiscretizer() const {
  return std::make_unique<CylindricalDiscretizer>();
}

std::unique_ptr<VariationGenerator> CylindricalSurface::MakeVariationGenerator() const {
  return std::make_unique<CylindricalVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> CylindricalSurface::MakeContactAnalyzer() const {
  return cylindrical::MakeContactAnalyzer();
}

std::unique_ptr<ResistanceLaw> CylindricalSurface::DoMakeLaw(std::string_view name) const {
  return cylindrical::MakeLaw(name);
}

std::vector<CharacteristicCheck> CylindricalSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  const metrology::ConformanceReport report = metrology::EvaluateCylindricalSms(part, sms);
  std::vector<CharacteristicCheck> checks;
  for (const auto& item : report.items) {
    if (!item.specified) continue;
    if (item.name == "size") {
      checks.push_back({"two_point_size_min", item.value_low, item.limit_low, item.limit_high});
      checks.push_back({"two_point_size_max", item.value, item.limit_low, item.limit_high});
    } else {
      checks.push_back({item.name, item.value, item.limit_low, item.limit_high});
    }
  }
  return checks;
}

std::shared_ptr<const Geometry> CylindricalSurface::DoParseGeometry(
    const PartSpec& part, const ConfigNode& geometry) const {
  const bool inner = part.role == Role::kInner;
  if (inner) {
    geometry.ExpectOnlyKeys({"length", "bore_diameter"});
  } else {
    geometry.ExpectOnlyKeys({"length", "outer_diameter"});
  }
  const double d = part.size.nominal;
  if (!(d > 0.0) || d > kMaxSize) {
    geometry.Fail("a part size (mating diameter) in (0, 10 m]",
                  FormatQuantity(d, Dimension::kLength));
  }
  const double length =
      geometry.Child("length").AsQuantityIn(Dimension::kLength, 0.0, kMaxSize, false);
  double outer_diameter = 0.0, bore_diameter = 0.0;
  if (inner) {
    if (auto node = geometry.Find("bore_diameter")) {
      bore_diameter = node->AsQuantityIn(Dimension::kLength, 0.0, kMaxSize);
      if (bore_diameter >= d) {
        node->Fail(
            "a bore diameter below the mating diameter " + FormatQuantity(d, Dimension::kLength),
            node->Describe());
      }
    }
  } else {
    const ConfigNode node = geometry.Child("outer_diameter");
    outer_diameter = node.AsQuantityIn(Dimension::kLength, 0.0, kMaxSize, false);
    if (outer_diameter <= d) {
      node.Fail(
          "a hub outer diameter above the mating diameter " + FormatQuantity(d, Dimension::kLength),
          node.Describe());
    }
  }
  return std::make_shared<CylindricalGeometry>(part.role, d, length, outer_diameter, bore_diameter);
}

void CylindricalSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                                     const ConfigNode& pair_node) const {
  // One nominal size for both parts (ISO 286 fits are defined on it); 1 nm absorbs unit
  // conversion rounding only.
  if (std::abs(inner.size.nominal - outer.size.nominal) > 1e-9) {
    pair_node.Fail("the same nominal diameter for both parts of a cylindrical fit",
                   "'" + inner.name + "' " +
                       FormatQuantity(inner.size.nominal, Dimension::kLength) + " and '" +
                       outer.name + "' " + FormatQuantity(outer.size.nominal, Dimension::kLength));
  }
}

}  // namespace fitfeel::cylindrical
