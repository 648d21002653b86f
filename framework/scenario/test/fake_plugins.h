#pragma once

#include "framework/model/surface_options.h"
#include "framework/plugin/registry.h"

namespace fitfeel::test {

// Registers in-process stand-ins for plugins, so the scenario tests need no plugin library:
//   test.surface.cylinder  forms axis_straightness, generatrix_straightness, roundness,
//                          cylindricity; laws gps, ve1; geometry {length} (inner) or
//                          {length, outer_diameter} (outer); the pair's nominal sizes must agree;
//                          model.options {tabulate} (FakeOptions).
//   test.surface.thread    renders_forces() == false and no law (like the helicoid stub).
//   test.device.fake       keys plugin, speed (> 0), radial_load (>= 0).
void RegisterFakePlugins(PluginRegistry& registry);

// test.surface.cylinder's parsed model.options.
struct FakeOptions final : SurfaceOptions {
  bool tabulate = false;
};

}  // namespace fitfeel::test
