#pragma once

#include "framework/collision/coarse_mesh.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::planar {

// The coarse meshes of a planar pair (see fitfeel::CoarseMeshes for the frames). Flat faces have
// no chordal error, so the meshes are the nominal solids themselves:
//  - inner (key or square shaft): a box b wide across x (z as well for four faces; else the
//    key's engaged height), from y = -length to y = 0;
//  - outer (keyway or square hole): walls facing each pair of faces across a slot b + 2 g wide,
//    from its entrance y = 0 to y = length, each wall b thick (how far the wall reaches does not
//    matter to the flanks' contact), g being a quarter of the sum of both size tolerances: the
//    per-face share of the fit's zone, so a centred key is free of the walls (the constrained
//    stage owns the mating) while the collision is within the fit's zone of the true faces.
// Throws UserError if a part's geometry is not planar.
CoarseMeshes MakePlanarCoarseMeshes(const PartSpec& inner, const PartSpec& outer);

}  // namespace fitfeel::planar
