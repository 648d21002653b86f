#include "surfaces/spherical/spherical_surface.h"

#include <cmath>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "surfaces/spherical/spherical_contact_analyzer.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_form.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/spherical_geometry.h"
#include "surfaces/spherical/spherical_law.h"

namespace fitfeel::spherical {

std::vector<FormCharacteristic> SphericalSurface::DoFormCharacteristics() const {
  return {FormCharacteristic::kRoundness, FormCharacteristic::kSphericity};
}

std::unique_ptr<Discretizer> SphericalSurface::DoMakeDiscretizer() const {
  return std::make_unique<SphericalDiscretizer>();
}

std::unique_ptr<VariationGenerator> SphericalSurface::DoMakeVariationGenerator() const {
  return std::make_unique<SphericalVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> SphericalSurface::DoMakeContactAnalyzer() const {
  return std::make_unique<SphericalContactAnalyzer>();
}

std::shared_ptr<const Geometry> SphericalSurface::DoParseGeometry(
    const PartSpec& part, const ConfigNode& geometry) const {
  return ParseSphericalGeometry(part, geometry);
}

void SphericalSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                                   const ConfigNode& pair_node) const {
  const SphericalGeometry& ball = GeometryOf(inner);
  const SphericalGeometry& socket = GeometryOf(outer);
  if (std::abs(inner.size.nominal - outer.size.nominal) > 1e-12) {
    const ConfigNode size = pair_node.Child(outer.name).Child("size");
    size.Fail("the ball's nominal sphere diameter (" +
                  FormatQuantity(inner.size.nominal, Dimension::kLength) + ")",
              size.Describe());
  }
  // The ball's band must cover the socket's: the socket cells are where contact is sought.
  if (ball.width() < socket.width()) {
    const ConfigNode width = pair_node.Child(inner.name).Child("geometry").Child("width");
    width.Fail("a ball band at least as wide as the socket's (" +
                   FormatQuantity(socket.width(), Dimension::kLength) + ")",
               width.Describe());
  }
}

std::unique_ptr<ResistanceLaw> SphericalSurface::DoMakeLaw(std::string_view name) const {
  if (name == "gps") return std::make_unique<KnuckleBearingLaw>();
  return nullptr;
}

std::vector<CharacteristicCheck> SphericalSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  return EvaluateSphereCharacteristics(part, sms);
}

// Both grids are centred on the sphere's centre, the centre of the rotation.
RenderMesh SphericalSurface::DoMakeRenderMesh(const PartSpec&, const SurfaceGrid& grid) const {
  return RevolutionRenderMesh(grid, 1.0, 0.0);
}

}  // namespace fitfeel::spherical
