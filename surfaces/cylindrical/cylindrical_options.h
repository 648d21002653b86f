#pragma once

#include <memory>

#include "framework/core/config_node.h"
#include "framework/model/model_settings.h"
#include "framework/model/surface_options.h"
#include "surfaces/cylindrical/elastic_options.h"

namespace fitfeel::cylindrical {

// How the dimensional variation is drawn (paper eq. 1 "rand(t_min, t_max)"), model.options key
// `size_draw`.
enum class SizeDraw {
  // per_part (default): one actual size per part, as a workpiece has, plus the local variation
  // of its form. The size is drawn uniformly among the sizes that keep every local size within
  // the limits given the part's form (the form's own two-point spread narrows the range the mean
  // size can take); when the form alone spreads wider than the tolerance, it is scaled back.
  kPerPart,
  // per_cell: the literal reading of eq. 1 per discrete point: white noise of the size
  // tolerance's amplitude. Its SMS meets the size limits but not, in general, form tolerances
  // tighter than the size tolerance (the noise itself is form error).
  kPerCell,
};

// Which size limits the final clamp (paper step 3) enforces, model.options key `size_limit`.
enum class SizeLimit {
  // two_point (default): every two-point size (ISO 14405-1 LP, opposite cells) within the limits.
  // The axis may bend and odd lobes may grow, as on a real part, without changing local sizes.
  kTwoPoint,
  // radial: eq. 2 read literally with V radial, lower/2 <= V <= upper/2 at every cell: the
  // surface stays between two coaxial cylinders at the limits around the nominal axis (stricter
  // than two-point sizes and than the envelope requirement).
  kRadial,
};

// The cylinder's `model.options` (README.md, "Scenario keys"), parsed once when the scene loads
// (CylindricalSurface::DoParseOptions): the variation generator's keys and the elastic law's.
struct CylindricalOptions final : SurfaceOptions {
  SizeDraw size_draw = SizeDraw::kPerPart;
  SizeLimit size_limit = SizeLimit::kTwoPoint;
  ElasticOptions elastic;
};

// Parses and checks a `model.options` map; throws ScenarioError at the offending key.
std::shared_ptr<const CylindricalOptions> ParseCylindricalOptions(const ConfigNode& options);

// The scene's parsed options, or the defaults when it has none.
inline CylindricalOptions CylindricalOptionsOf(const ModelSettings& settings) {
  return OptionsAs<CylindricalOptions>(settings.options);
}

}  // namespace fitfeel::cylindrical
