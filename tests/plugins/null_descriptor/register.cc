// Deliberately broken test plugin: its hook returns a null descriptor.
#include "framework/plugin/plugin_entry.h"

extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register() {
  return nullptr;
}
