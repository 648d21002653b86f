#pragma once

#include "framework/model/surface_type.h"

namespace fitfeel::cylindrical {

// Shaft in bushing, pin in hole: the paper's cylindrical mating (plugin
// fitfeel.surface.cylindrical). Geometry keys: `length` for both parts, `outer_diameter` (hub
// outer diameter d2 > d) for the outer part, optional `bore_diameter` (hollow shaft, < d) for the
// inner part; the mating diameter d is the part's nominal size.
class CylindricalSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override;
  std::vector<std::string> DoLawNames() const override;
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;
  // Shaft: a closed prism; bushing: a tube; see cylindrical_coarse_mesh.h for sizes and facets.
  CoarseMeshes DoMakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const override;
  LeadIn DoMakeLeadIn(const PartSpec& inner, const PartSpec& outer) const override;

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& geometry) const override;
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override;
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override;
  RenderMesh DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const override;
  // model.options: the generator's keys and the elastic law's (CylindricalOptions).
  std::shared_ptr<const SurfaceOptions> DoParseOptions(const ConfigNode& options) const override;
  // The elastic law's worst case (elastic_cost.h); the other laws' prepare is the cells'.
  double DoEstimatePrepareSeconds(const ModelSettings& model, const GridShape& inner,
                                  const GridShape& outer, double depth_steps) const override;
  // sms_conformance.h's evaluation (EvaluateCylindricalSms): two-point sizes as
  // two_point_size_min / two_point_size_max against the size limits, then each specified form
  // tolerance.
  std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const override;
};

}  // namespace fitfeel::cylindrical
