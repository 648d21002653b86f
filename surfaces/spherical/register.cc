// The spherical plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/spherical/spherical_surface.h"

namespace {
constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::SurfaceEntry<fitfeel::spherical::SphericalSurface>(
        "fitfeel.surface.spherical", "1.0.0",
        "Ball in socket: spherical plain (knuckle) bearing, ISO 12240-1; friction torque"),
};
constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);
}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
