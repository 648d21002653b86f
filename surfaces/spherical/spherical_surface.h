#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/surface_type.h"

namespace fitfeel::spherical {

// fitfeel.surface.spherical: ball (inner ring) in socket (outer ring) of a spherical plain
// bearing (ISO 12240-1). Characteristics: size (two-point through the centre), roundness,
// sphericity. The constrained motion is the rotation about the bearing axis (rotational()).
// Law "gps": thick-shell pressure per cell, friction torque (see spherical_law.h).
class SphericalSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override;
  std::vector<std::string> DoLawNames() const override { return {"gps"}; }
  bool DoRotational() const override { return true; }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& geometry) const override;
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override;
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override;
  RenderMesh DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const override;
  std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const override;
};

}  // namespace fitfeel::spherical
