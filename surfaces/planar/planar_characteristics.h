#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"
#include "framework/model/surface_type.h"
#include "surfaces/planar/planar_form.h"
#include "surfaces/planar/planar_discretizer.h"

namespace fitfeel::planar {

// The cells of one face: y along the sliding direction, `across` along the face's height (z for the
// faces normal to x, x for those normal to z), and `values` (a variation or a part of it).
struct FaceSamples {
  std::vector<double> y, across, v;
};
FaceSamples SamplesOf(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                      const Eigen::VectorXd& values);

// Largest minimum-zone straightness of the face's lines along y (one per strip across the
// height): the generatrix straightness of a flank along which the key slides.
double FaceStraightness(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                        const Eigen::VectorXd& values);
// Minimum-zone flatness of the face.
PlaneZone FaceFlatness(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                       const Eigen::VectorXd& values);
// Parallelism of the pair's faces, each to the other as datum (ISO 1101: the toleranced face
// between two planes parallel to the datum plane), the larger of the two. The datum plane's
// orientation is that of the datum face's minimum-zone plane (ISO 5459 associates a datum plane
// by a constrained minimax fit; for form deviations far below the face's size its orientation is
// the minimum-zone one). The faces' outward normals are opposite, so the datum face's slopes enter
// with the opposite sign.
double PairParallelism(const SurfaceGrid& grid, const FaceLayout& layout, int pair,
                       const Eigen::VectorXd& values);

// Straightness of the pair's median line along y (ISO 1101, a median line's straightness), per
// strip across the height: the median of a pair of faces normal to +-x sits at x = (V+ - V-) / 2.
double PairAxisStraightness(const SurfaceGrid& grid, const FaceLayout& layout, int pair,
                            const Eigen::VectorXd& values);

// Every characteristic of the part's spec, evaluated on the skin model shape: the smallest and the
// largest two-point size (opposite cells of a pair; ISO 14405-1 default) against the size limits,
// then straightness, flatness, parallelism and axis straightness (largest over faces or pairs)
// when the spec has them.
std::vector<CharacteristicCheck> EvaluatePlanarCharacteristics(const PartSpec& part,
                                                               const SkinModelShape& sms);

}  // namespace fitfeel::planar
