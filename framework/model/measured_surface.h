#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/export.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel {

// A part measured instead of drawn (docs/measured-parts.md): the samples of a roundness
// instrument, a straightness (generatrix) instrument or a CMM, in the part's mating frame.
enum class MeasurementKind {
  kRoundness,     // traces at several heights, each over the angle
  kStraightness,  // traces at several angles, each along the axis
  kPoints,        // a point cloud (x, y, z), y along the mating axis
};

FITFEEL_API const char* MeasurementKindName(MeasurementKind kind);

struct MeasuredSurface {
  MeasurementKind kind = MeasurementKind::kRoundness;
  std::filesystem::path file;
  // One entry per sample, SI: axial position y (m), direction angle beta in [0, 2 pi) (rad) and
  // the radial value: the radius (m) when `absolute`, else the deviation from the nominal radius
  // (m, positive away from the axis: V of the skin model shape).
  std::vector<double> height, angle, value;
  bool absolute = false;
  int traces = 0;  // distinct heights (roundness) or angles (straightness); 0 for a point cloud
  // The scenario key that named the file, for refusals found once the grid is known.
  SourceLocation key_location;
  std::string key_path;
};

// True when `grid` is a cylinder's of `nominal_radius` (every cell centre on it, radial normals,
// columns ascending): the grids MeasuredSkinModelShape resamples onto.
FITFEEL_API bool IsCylinderGrid(const SurfaceGrid& grid, double nominal_radius);

// The skin model shape of a measured part on `grid`, a cylinder's grid (every cell centre at
// `nominal_radius` from the axis, radial normals). V per cell:
//  - roundness: periodic linear interpolation in angle along each trace, then linear in height
//    between the traces, held constant beyond the first and last trace;
//  - straightness: linear in height along each trace (held beyond its ends), then periodic linear
//    in angle between the traces;
//  - points: the mean of the samples nearest each cell (rows and columns split halfway between
//    their centres); cells without a sample interpolated around their row, rows without one
//    between the nearest rows (held beyond the ends).
// A sample exactly at a cell's height and angle gives that cell its value bit for bit, so a
// shape written by MeasurementCsv reads back unchanged. The shape's parts: dimension = the mean
// of V, form = V minus it, no sampled texture (a measured profile is already filtered).
// Throws UnsupportedError for a grid that is not a cylinder's.
FITFEEL_API SkinModelShape MeasuredSkinModelShape(const MeasuredSurface& measured,
                                                  const SurfaceGrid& grid, double nominal_radius);

// A skin model shape as a roundness measurement file: one trace per row, one sample per column,
// in SI units with the shortest decimals that read back exactly
// ("height [m],angle [rad],deviation [m]"). `comment` is written first as '#' lines.
FITFEEL_API std::string MeasurementCsv(const SkinModelShape& sms, const std::string& comment);

}  // namespace fitfeel
