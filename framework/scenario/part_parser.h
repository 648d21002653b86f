#pragma once

#include <string>

#include "framework/core/config_node.h"
#include "framework/model/gps_spec.h"
#include "framework/model/surface_type.h"

namespace fitfeel::scenario {

// Physical and sanity bounds of the scenario's values, in SI. Each is chosen from what a machined
// part or a haptic run can be, never to make an output look right; docs/scenario-format.md lists
// them for users.
namespace limits {
// ISO 286-1 defines standard tolerances up to 3150 mm; explicit deviations are allowed that far.
inline constexpr double kMaxNominal = 3.15;
// Ra and Rz of machined surfaces stay well below 1 mm (rough sawing: Rz about 0.1 mm).
inline constexpr double kMaxTexture = 1e-3;
// From soft engineering elastomers (a few MPa) to diamond (about 1.05-1.2 TPa).
inline constexpr double kMinYoungsModulus = 1e6;
inline constexpr double kMaxYoungsModulus = 1.2e12;
}  // namespace limits

// Parses everything the scenario says about one part except its geometry (role, size, form,
// texture, material); the caller hands `node.geometry` to the surface plugin. Throws
// ScenarioError at the offending key.
PartSpec ParsePart(const std::string& name, const ConfigNode& node, const SurfaceType& surface,
                   const std::string& surface_id);

// The part's `size`: "20 mm H7" (ISO 286 code, looked up in the standard's tables), "M10x1.5 6g"
// (ISO 965-1 thread designation: pitch-diameter deviations, pitch and crest deviations) or
// {nominal, lower, upper} deviations.
SizeSpec ParseSize(const ConfigNode& node, Role role);

}  // namespace fitfeel::scenario
