// The thread stub plugin's only exported symbol.
#include "framework/plugin/plugin_entry.h"
#include "surfaces/thread/thread_surface.h"

namespace {

constexpr FitfeelPluginEntry kEntries[] = {
    fitfeel::plugin::SurfaceEntry<fitfeel::thread::ThreadSurface>(
        "fitfeel.surface.thread", "0.1.0",
        "Threaded (helicoid) mating: geometry and skin model shapes only, no resistance law yet"),
};

constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);

}  // namespace

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return &kDescriptor;
}
