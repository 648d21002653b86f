#include "surfaces/conical/conical_surface.h"
#include "surfaces/conical/conical_coarse_mesh.h"

#include <cmath>

#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/core/quantity.h"
#include "surfaces/conical/conical_contact_analyzer.h"
#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/conical_form.h"
#include "surfaces/conical/conical_generator.h"
#include "surfaces/conical/conical_geometry.h"
#include "surfaces/conical/conical_law.h"

namespace fitfeel::conical {

std::vector<FormCharacteristic> ConicalSurface::DoFormCharacteristics() const {
  return {FormCharacteristic::kAxisStraightness, FormCharacteristic::kGeneratrixStraightness,
          FormCharacteristic::kRoundness};
}

std::unique_ptr<Discretizer> ConicalSurface::DoMakeDiscretizer() const {
  return std::make_unique<ConicalDiscretizer>();
}

std::unique_ptr<VariationGenerator> ConicalSurface::DoMakeVariationGenerator() const {
  return std::make_unique<ConicalVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> ConicalSurface::DoMakeContactAnalyzer() const {
  return std::make_unique<ConicalContactAnalyzer>();
}

std::shared_ptr<const Geometry> ConicalSurface::DoParseGeometry(const PartSpec& part,
                                                                const ConfigNode& geometry) const {
  return ParseConicalGeometry(part, geometry);
}

void ConicalSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                                 const ConfigNode& pair_node) const {
  const ConicalGeometry& pin = GeometryOf(inner);
  const ConicalGeometry& hole = GeometryOf(outer);
  const ConfigNode outer_node = pair_node.Child(outer.name);
  // One taper for both: a pin of another taper touches along a circle, not a surface, and the
  // clearance would no longer be uniform along the joint.
  if (std::abs(pin.taper() - hole.taper()) > 1e-9 * hole.taper()) {
    const ConfigNode taper = outer_node.Child("geometry").Child("taper");
    taper.Fail("the pin's taper (1:" + MessageNumber(1.0 / pin.taper()) + ")", taper.Describe());
  }
  // The size of both is the small-end diameter, and the hole's small end is where the pin seats.
  if (std::abs(inner.size.nominal - outer.size.nominal) > 1e-12) {
    const ConfigNode size = outer_node.Child("size");
    size.Fail("the pin's nominal small-end diameter (" +
                  FormatQuantity(inner.size.nominal, Dimension::kLength) + ")",
              size.Describe());
  }
}

std::unique_ptr<ResistanceLaw> ConicalSurface::DoMakeLaw(std::string_view name) const {
  if (name == "gps") return std::make_unique<TaperPressFitLaw>();
  return nullptr;
}

std::vector<CharacteristicCheck> ConicalSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  return EvaluateConeCharacteristics(part, sms);
}

CoarseMeshes ConicalSurface::DoMakeCoarseMeshes(const PartSpec& inner,
                                                const PartSpec& outer) const {
  return MakeConicalCoarseMeshes(inner, outer);
}

LeadIn ConicalSurface::DoMakeLeadIn(const PartSpec& inner, const PartSpec& outer) const {
  return MakeConicalLeadIn(inner, outer);
}

// The pin's rows are measured from its small (leading) end back along the body, so the moving
// frame mirrors them; the hole's rows start at its entrance, as the fixed frame does.
RenderMesh ConicalSurface::DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const {
  return RevolutionRenderMesh(grid, part.role == Role::kInner ? -1.0 : 1.0, 0.0);
}

}  // namespace fitfeel::conical
