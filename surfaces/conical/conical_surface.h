#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/surface_type.h"

namespace fitfeel::conical {

// fitfeel.surface.conical: taper pin (inner) in a taper-reamed hole (outer), ISO 2339 1:50.
// Characteristics: size (two-point), axis straightness, generatrix straightness, roundness.
// Law "gps": DIN 7190 taper press fit per cell (see conical_law.h).
class ConicalSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override;
  std::vector<std::string> DoLawNames() const override { return {"gps"}; }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;
  CoarseMeshes DoMakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const override;
  LeadIn DoMakeLeadIn(const PartSpec& inner, const PartSpec& outer) const override;

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& geometry) const override;
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override;
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override;
  RenderMesh DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const override;
  std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const override;
};

}  // namespace fitfeel::conical
