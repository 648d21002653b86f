// The planar surface plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/planar/planar_surface.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::SurfaceEntry<fitfeel::planar::PlanarSurface>(
        "fitfeel.surface.planar", "1.0.0",
        "Parallel key in keyway, square shaft in square hole (flat faces sliding along y)"),
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
