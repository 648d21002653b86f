#pragma once

#include "framework/collision/coarse_mesh.h"
#include "framework/collision/lead_in.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::cylindrical {

// Most facets a coarse mesh gets: 256 keep the chordal error below 7.6e-5 of the radius (0.76 um
// on a 20 mm fit), finer than any free-motion contact needs, at 2048 tube triangles.
inline constexpr int kMaxCoarseFacets = 256;

// Facets of both coarse meshes of a fit: the fewest whose chordal error at the nominal radius is
// at most the radial width of the fit's zone, (T_hole + T_shaft) / 2 (the spread of the per-side
// play or interference over all parts within tolerance), so that the coarse geometry is no
// cruder than the fit's own tolerance; at least 8, at most kMaxCoarseFacets. H7/g6 at 20 mm:
// (21 + 13) / 2 = 17 um -> 54 facets.
int CoarseFacets(const PartSpec& inner, const PartSpec& outer);

// The coarse meshes of a cylindrical pair (see fitfeel::CoarseMeshes for the frames), both at the
// nominal diameter d the parts share:
//  - inner (shaft or pin): a closed prism inscribed in the circle of d / 2, from y = -length to
//    y = 0 (its leading end at the origin); a hollow shaft's bore is not meshed (nothing enters
//    it in free motion);
//  - outer (bushing or hole): a tube from y = 0 (its mating surface's start; an entrance chamfer
//    lies in front of it, from y = -chamfer length) to y = length, its outer wall on
//    the circle of the hub's outer diameter d2, its bore a polygon circumscribing the circle of
//    d / 2 with its vertices at the shaft's vertex angles.
// The two polygons are then similar, the bore's larger by 1 / cos(pi / n): a centred shaft is
// free of the bore by the chordal error r (1 - cos(pi / n)) all round and the coarse meshes
// never collide where the constrained stage owns the contact; the mating itself (play or
// interference within micrometres) is the constrained stage's. Throws UserError if a part's
// geometry is not cylindrical.
CoarseMeshes MakeCylindricalCoarseMeshes(const PartSpec& inner, const PartSpec& outer);

// The lead-in of a cylindrical pair, the shaft moving (docs/lead-in.md): both parts at the middle
// of their size zones (the play a typical pair has), the shaft's end narrowed by its chamfer, the
// bore widened by its own in front of the mating surface (its face at y = -chamfer length), the
// constrained stage taking over once the shaft's chamfer has passed the bore's edge (y = the
// shaft's chamfer length), or where an interference fit wedges on the axis before that.
LeadIn MakeCylindricalLeadIn(const PartSpec& inner, const PartSpec& outer);

}  // namespace fitfeel::cylindrical
