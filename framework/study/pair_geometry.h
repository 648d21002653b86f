#pragma once

#include <optional>

#include "framework/core/export.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel::study {

// What a metrologist would say of a drawn part pair before it is assembled.
struct PairGeometry {
  double inner_size = 0.0;  // actual size of the inner part: diametral deviation from nominal, m
  double outer_size = 0.0;  // the same for the outer part
  // Circular cylinders only: across each diameter, the room between the bore's narrowest
  // sections and the shaft's widest ones, least over all directions, m. With
  // g(theta) = min over outer rows of r_o(theta) - max over inner rows of r_i(theta), it is the
  // least g(theta) + g(theta + pi). During a full insertion every section of the shaft passes
  // every section of the bore, so each g is met somewhere; the two sides of a diameter may be
  // met at different depths, which makes this a lower bound on the room a rigid, untilted
  // insertion finds: positive means the pair passes without touching, negative that it may have
  // to deform (the run's `interfering` says whether it did).
  std::optional<double> min_clearance;
};

// Sizes as the mean of the per-cell size draws (one actual size per part), times two; the
// clearance when both grids are circular cylinders about the mating axis (cell centres at one
// radius), absent otherwise.
FITFEEL_API PairGeometry MeasurePair(const SkinModelShape& inner, const SkinModelShape& outer);

}  // namespace fitfeel::study
