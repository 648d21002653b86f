#pragma once

#include <vector>

#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel {

// Axial boundaries of a grid's rows (m + 1 of them), measured from the first boundary: halfway
// between neighbouring row centres, the outer ones half a row beyond the end centres; a one-row
// grid spans the part's mating length. Analyzers map the rows of two parts onto each other
// through these. Throws UserError naming the part if the rows are not in increasing axial order,
// do not match the row count, or a one-row grid has no length.
std::vector<double> RowEdges(const PartSpec& part, const SurfaceGrid& grid);

}  // namespace fitfeel
