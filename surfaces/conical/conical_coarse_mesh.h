#pragma once

#include "framework/collision/coarse_mesh.h"
#include "framework/collision/lead_in.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::conical {

// Most facets a coarse mesh gets (as the cylindrical surface's).
inline constexpr int kMaxCoarseFacets = 256;

// The coarse meshes of a taper pair (see fitfeel::CoarseMeshes for the frames), at nominal size:
//  - inner (pin): a closed frustum inscribed in the pin's cone, its small end (diameter d)
//    leading at y = 0, its large end (d + C L) at y = -L;
//  - outer (hole): a tube from its entrance (its large end, d + C L_hole) at y = 0 to its small
//    end (d) at y = L_hole, its bore circumscribing the hole's cone, its outer wall on the hub's
//    outer diameter.
// Facets: the fewest whose chordal error at the pin's large radius is at most the fit's radial
// zone, (T_pin + T_hole) / 2, at least 8, at most kMaxCoarseFacets. A centred pin is then free of
// the hole until the small ends meet (the nominal clearance (L_hole - s) tan(alpha) only grows the
// gap), and the coarse geometry is no cruder than the fit's tolerance. Throws UserError if a
// part's geometry is not conical.
// Chamfers (ConicalGeometry::chamfer) narrow the pin's small end and widen the hole's entrance in
// front of it (from y = -chamfer length), as the lead-in has them.
CoarseMeshes MakeConicalCoarseMeshes(const PartSpec& inner, const PartSpec& outer);

// The lead-in of a taper pair, the pin moving (docs/lead-in.md): both parts at the middle of their
// size zones, the pin's radius growing behind its chamfered small end at the taper, the hole's
// narrowing behind its chamfered entrance; the constrained stage's depth counts from where the
// pin's chamfer has passed the hole's edge (or the cones wedge, if sooner). The cones themselves
// form a funnel: the play (L - s) tan(alpha) closes as the pin goes in.
LeadIn MakeConicalLeadIn(const PartSpec& inner, const PartSpec& outer);

}  // namespace fitfeel::conical
