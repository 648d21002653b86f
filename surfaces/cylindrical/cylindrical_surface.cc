#include "surfaces/cylindrical/cylindrical_surface.h"

#include <cmath>

#include <algorithm>
#include <string>

#include "surfaces/cylindrical/sms_conformance.h"
#include "surfaces/cylindrical/cylindrical_coarse_mesh.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/cylindrical_generator.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/cylindrical_options.h"
#include "surfaces/cylindrical/elastic_cost.h"

namespace fitfeel::cylindrical {
std::vector<FormCharacteristic> CylindricalSurface::DoFormCharacteristics() const {
  return {FormCharacteristic::kAxisStraightness, FormCharacteristic::kGeneratrixStraightness,
          FormCharacteristic::kRoundness, FormCharacteristic::kCylindricity};
}

// "gps" (the paper's eqs. 9-12), "elastic" (harmonic-compliance contact checked against FEM,
// docs/contact-mechanics.md) and "ve1" (the paper's ideal-geometry baseline).
std::vector<std::string> CylindricalSurface::DoLawNames() const {
  return {"gps", "elastic", "ve1"};
}

std::unique_ptr<Discretizer> CylindricalSurface::DoMakeDiscretizer() const {
  return std::make_unique<CylindricalDiscretizer>();
}

std::unique_ptr<VariationGenerator> CylindricalSurface::DoMakeVariationGenerator() const {
  return std::make_unique<CylindricalVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> CylindricalSurface::DoMakeContactAnalyzer() const {
  return std::make_unique<CylinderContactAnalyzer>();
}

CoarseMeshes CylindricalSurface::DoMakeCoarseMeshes(const PartSpec& inner,
                                                  const PartSpec& outer) const {
  return MakeCylindricalCoarseMeshes(inner, outer);
}

LeadIn CylindricalSurface::DoMakeLeadIn(const PartSpec& inner, const PartSpec& outer) const {
  return MakeCylindricalLeadIn(inner, outer);
}

std::unique_ptr<ResistanceLaw> CylindricalSurface::DoMakeLaw(std::string_view name) const {
  if (name == "gps") return std::make_unique<GpsLaw>();
  if (name == "elastic") return std::make_unique<ElasticLaw>();
  if (name == "ve1") return std::make_unique<Ve1Law>();
  return nullptr;
}

std::shared_ptr<const SurfaceOptions> CylindricalSurface::DoParseOptions(
    const ConfigNode& options) const {
  return ParseCylindricalOptions(options);
}

double CylindricalSurface::DoEstimatePrepareSeconds(const ModelSettings& model,
                                                    const GridShape& inner, const GridShape& outer,
                                                    double depth_steps) const {
  if (model.law != "elastic") return 0.0;
  return ElasticPrepareSeconds(CylindricalOptionsOf(model).elastic,
                               std::max(inner.rows, outer.rows),
                               std::max(inner.columns, outer.columns), depth_steps);
}

std::vector<CharacteristicCheck> CylindricalSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  const ConformanceReport report = EvaluateCylindricalSms(part, sms);
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
  return ParseCylindricalGeometry(part, geometry);
}

void CylindricalSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                                     const ConfigNode& pair_node) const {
  CheckCylindricalPair(inner, outer, pair_node);
}

// Rows run from y = 0 at equal pitch; the shaft's leading end is its last row's far edge (the
// analyzer's convention), which the moving frame puts at the origin.
RenderMesh CylindricalSurface::DoMakeRenderMesh(const PartSpec& part,
                                                const SurfaceGrid& grid) const {
  const double length = grid.row_position[0] + grid.row_position[grid.rows - 1];
  return RevolutionRenderMesh(grid, 1.0, part.role == Role::kInner ? -length : 0.0);
}

}  // namespace fitfeel::cylindrical
