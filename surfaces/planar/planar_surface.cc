#include "surfaces/planar/planar_surface.h"
#include "surfaces/planar/planar_coarse_mesh.h"

#include <cmath>

#include "framework/core/quantity.h"
#include "surfaces/planar/planar_characteristics.h"
#include "surfaces/planar/planar_contact_analyzer.h"
#include "surfaces/planar/planar_generator.h"
#include "surfaces/planar/planar_geometry.h"
#include "surfaces/planar/planar_discretizer.h"
#include "surfaces/planar/planar_law.h"

namespace fitfeel::planar {

std::vector<FormCharacteristic> PlanarSurface::DoFormCharacteristics() const {
  return {FormCharacteristic::kStraightness, FormCharacteristic::kFlatness,
          FormCharacteristic::kParallelism, FormCharacteristic::kAxisStraightness};
}

std::unique_ptr<Discretizer> PlanarSurface::DoMakeDiscretizer() const {
  return std::make_unique<PlanarDiscretizer>();
}

std::unique_ptr<VariationGenerator> PlanarSurface::DoMakeVariationGenerator() const {
  return std::make_unique<PlanarVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> PlanarSurface::DoMakeContactAnalyzer() const {
  return std::make_unique<PlanarContactAnalyzer>();
}

std::shared_ptr<const Geometry> PlanarSurface::DoParseGeometry(const PartSpec& part,
                                                               const ConfigNode& geometry) const {
  return ParsePlanarGeometry(part, geometry);
}

void PlanarSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                                const ConfigNode& pair_node) const {
  const PlanarGeometry& a = PlanarGeometryOf(inner);
  const PlanarGeometry& b = PlanarGeometryOf(outer);
  // The variations of both parts are deviations from one nominal width (eq. 8 subtracts them).
  if (std::abs(a.width() - b.width()) > 1e-12) {
    pair_node.Fail("equal nominal sizes of '" + inner.name + "' and '" + outer.name +
                       "' (a key and its keyway share the nominal width)",
                   FormatQuantity(a.width(), Dimension::kLength) + " and " +
                       FormatQuantity(b.width(), Dimension::kLength));
  }
  if (a.faces() != b.faces()) {
    pair_node.Fail("the same number of faces on '" + inner.name + "' and '" + outer.name + "'",
                   std::to_string(a.faces()) + " and " + std::to_string(b.faces()));
  }
  // Cells face each other strip by strip: both parts describe the same contact strip.
  if (std::abs(a.height() - b.height()) > 1e-12) {
    pair_node.Fail("the same contact height on '" + inner.name + "' and '" + outer.name +
                       "' (the flank height in contact)",
                   FormatQuantity(a.height(), Dimension::kLength) + " and " +
                       FormatQuantity(b.height(), Dimension::kLength));
  }
}

std::unique_ptr<ResistanceLaw> PlanarSurface::DoMakeLaw(std::string_view name) const {
  if (name == "gps") return std::make_unique<PlanarGpsLaw>();
  return nullptr;
}

std::vector<CharacteristicCheck> PlanarSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  return EvaluatePlanarCharacteristics(part, sms);
}

CoarseMeshes PlanarSurface::DoMakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const {
  return MakePlanarCoarseMeshes(inner, outer);
}

LeadIn PlanarSurface::DoMakeLeadIn(const PartSpec& inner, const PartSpec& outer) const {
  const PlanarGeometry& key = PlanarGeometryOf(inner);
  const PlanarGeometry& slot = PlanarGeometryOf(outer);
  const Chamfer& end = key.chamfer();
  const Chamfer& entrance = slot.chamfer();
  RadiusProfile moving, fixed;
  moving.points.emplace_back(0.0, 0.5 * inner.size.mid_size() - end.width());
  if (end.length > 0.0) moving.points.emplace_back(end.length, 0.5 * inner.size.mid_size());
  fixed.points.emplace_back(0.0, 0.5 * outer.size.mid_size() + entrance.width());
  if (entrance.length > 0.0) fixed.points.emplace_back(entrance.length, 0.5 * outer.size.mid_size());
  return LeadIn(moving, fixed, -entrance.length, end.length,
                key.faces() == 2 ? LeadIn::Section::kAcrossX : LeadIn::Section::kSquare);
}

// Strips of one face are height / columns-per-face wide; the inner part's leading end is its last
// row's far edge (the analyzer's shift depth - inner length), put at the origin.
RenderMesh PlanarSurface::DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const {
  const double width = PlanarGeometryOf(part).height() / LayoutOf(grid).columns_per_face;
  const double length = grid.row_position[0] + grid.row_position[grid.rows - 1];
  return FlatCellRenderMesh(grid, width, 1.0, part.role == Role::kInner ? -length : 0.0);
}

}  // namespace fitfeel::planar
