#pragma once

#include "framework/plugin/registry.h"

namespace fitfeel::plot::testing {

// In-process stand-ins so that the scene pipeline of the plot commands runs without plugin
// libraries:
//   test.plot.cylinder  geometry {length}; forms roundness; laws lame (pressure 5.8333 MPa per um,
//                       the oracle's steel pair) and ideal (no pressure model); a discretizer of
//                       the requested rows x columns over the length, a generator drawing V
//                       uniformly inside the size limits from the scene's generator, an analyzer
//                       whose interference is max(0, V_inner - min V_outer) per inner cell.
//   test.plot.device    no keys besides plugin.
void RegisterPlotFakes(PluginRegistry& registry);

}  // namespace fitfeel::plot::testing
