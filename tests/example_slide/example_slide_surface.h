#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/surface_type.h"

namespace fitfeel::example_slide {

// fitfeel.surface.example_slide: a block sliding in a slot between two rails, size only, with the
// "spring" law. The guide's example (surfaces/README.md).
class SlideSurface final : public SurfaceType {
 protected:
  // Size only: any form tolerance in a scenario is refused by the scenario parser.
  std::vector<FormCharacteristic> DoFormCharacteristics() const override { return {}; }
  std::vector<std::string> DoLawNames() const override { return {"spring"}; }

  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& geometry) const override;
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override;
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override;
  std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const override;
};

}  // namespace fitfeel::example_slide
