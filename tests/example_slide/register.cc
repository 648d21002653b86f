// The example slide plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "tests/example_slide/example_slide_surface.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::SurfaceEntry<fitfeel::example_slide::SlideSurface>(
        "fitfeel.surface.example_slide", "1.0.0",
        "Guide example: a block sliding in a slot between two rails (size only)"),
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
