// The conical plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/conical/conical_surface.h"

namespace {
constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::SurfaceEntry<fitfeel::conical::ConicalSurface>(
        "fitfeel.surface.conical", "1.0.0",
        "Taper pin in a taper-reamed hole (ISO 2339 1:50), DIN 7190 press fit"),
};
constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);
}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
