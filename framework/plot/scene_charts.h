#pragma once

#include <string>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"
#include "framework/model/skin_model_shape.h"
#include "framework/plot/figure.h"
#include "framework/plot/pressure_chart.h"
#include "framework/plot/run_record.h"

namespace fitfeel::plot {

// Charts of a prepared scene, whatever built it (the runtime's Prepare, or a test).

// `fitfeel plot sms`: the unwrapped skin profile of each part and, for parts mated by insertion
// (`translational`), the tolerance space at full insertion (FullInsertionDepth); a subtitle says
// why that map is missing when it cannot be drawn. With `only_part` set, that part's profile
// alone. Throws UserError naming the parts when `only_part` is neither.
FITFEEL_API HeatMapChart MakeSceneSmsChart(const std::string& scenario, const PartSpec& inner,
                                           const SkinModelShape& inner_sms, const PartSpec& outer,
                                           const SkinModelShape& outer_sms, bool translational,
                                           const std::string& only_part = "");

// `fitfeel plot pressure`: the interference map of the analyzer at `depth_mm` (with the radial
// offset (offset_x_um, offset_z_um) and twist the run recorded at the nearest tick; for an older
// trace without the offset columns, the device position x_mm, z_mm, said in `pose_note`; taken
// into the analyzer's frame for the scene's `moving` part, AnalyzerPose), turned into pressure by
// the law, and that tick's forces in the same frame. Throws UserError for a depth outside the
// run's constrained range and UnsupportedError for a law or analyzer that cannot give a pressure
// map.
FITFEEL_API PressureMapData MakePressureData(const RunRecord& run, double depth_mm,
                                             const ContactAnalyzer& analyzer,
                                             const ResistanceLaw& law,
                                             const SurfaceGrid& inner_grid,
                                             Role moving = Role::kInner);

}  // namespace fitfeel::plot
