#include "framework/cad/cad_document.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace fitfeel::cad {

const char* SurfaceKindName(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::kPlane:
      return "plane";
    case SurfaceKind::kCylinder:
      return "cylinder";
    case SurfaceKind::kCone:
      return "cone";
    case SurfaceKind::kSphere:
      return "sphere";
    case SurfaceKind::kBSpline:
      return "B-spline";
    case SurfaceKind::kOther:
      break;
  }
  return "other";
}

const char* ToleranceKindName(ToleranceKind kind) {
  switch (kind) {
    case ToleranceKind::kSize:
      return "size";
    case ToleranceKind::kRoundness:
      return "roundness";
    case ToleranceKind::kCylindricity:
      return "cylindricity";
    case ToleranceKind::kStraightness:
      return "straightness";
    case ToleranceKind::kFlatness:
      return "flatness";
    case ToleranceKind::kOther:
      break;
  }
  return "other";
}

NLOHMANN_JSON_SERIALIZE_ENUM(SurfaceKind, {{SurfaceKind::kOther, "other"},
                                           {SurfaceKind::kPlane, "plane"},
                                           {SurfaceKind::kCylinder, "cylinder"},
                                           {SurfaceKind::kCone, "cone"},
                                           {SurfaceKind::kSphere, "sphere"},
                                           {SurfaceKind::kBSpline, "bspline"}})
NLOHMANN_JSON_SERIALIZE_ENUM(ToleranceKind, {{ToleranceKind::kOther, "other"},
                                             {ToleranceKind::kSize, "size"},
                                             {ToleranceKind::kRoundness, "roundness"},
                                             {ToleranceKind::kCylindricity, "cylindricity"},
                                             {ToleranceKind::kStraightness, "straightness"},
                                             {ToleranceKind::kFlatness, "flatness"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CadFace, entity, kind, surface_type, origin, axis, radius,
                                   semi_angle, axial_min, axial_max, convex, samples)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CadTolerance, kind, type, faces, value, has_plus_minus, lower,
                                   has_range, upper, iso_class, hole_class)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(CadPart, name, faces, datums, mesh, mesh_note)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CadDocument, schema, length_unit, parts, tolerances)

std::string ToText(const CadDocument& document) {
  // Doubles as 17 significant digits: the parent reads back exactly what the child computed.
  return nlohmann::json(document).dump();
}

CadDocument FromText(const std::string& text) {
  try {
    return nlohmann::json::parse(text).get<CadDocument>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("the reader's answer is not a document: ") + e.what());
  }
}

}  // namespace fitfeel::cad
