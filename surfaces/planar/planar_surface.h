#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/surface_type.h"

namespace fitfeel::planar {

// fitfeel.surface.planar: a parallel key in its keyway, a square shaft in its square hole (paper
// Table 1: size, straightness, flatness; and parallelism of a pair of faces).
class PlanarSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override;
  std::vector<std::string> DoLawNames() const override { return {"gps"}; }

  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;
  CoarseMeshes DoMakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const override;
  // The key's or square's lead-in (docs/lead-in.md): half-widths across the flats at the middle
  // of the size zones, narrowed by the moving part's chamfer and widened by the fixed one's, in
  // front of the faces; a key is constrained across its flanks only, a square on both axes.
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

}  // namespace fitfeel::planar
