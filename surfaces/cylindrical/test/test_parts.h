#pragma once

#include <memory>
#include <string>

#include "framework/model/gps_spec.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"

namespace fitfeel::cylindrical::testing {

// A part with cylindrical geometry; lengths in metres, deviations of the diameter in metres.
PartSpec Part(std::string name, Role role, double diameter, double length, double lower,
              double upper);

// Paper Table 2 (20 mm shaft js6 +-8 um diameter in a hole 0/+25 um; axis straightness and
// roundness 10 um; waviness 3.2 um, Ra 0.4 um, Rz 1.6 um). Shaft 60 mm long, bushing 20 mm long
// with a 30 mm hub.
PartSpec PaperShaft();
PartSpec PaperHole();

}  // namespace fitfeel::cylindrical::testing
