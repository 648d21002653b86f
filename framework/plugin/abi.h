#pragma once

// The only contract between the plugin loader and a plugin library. Each plugin library exports
// exactly one symbol, FITFEEL_PLUGIN_HOOK_NAME, returning a descriptor checked field by field
// before anything else in it is used (ABI version, sizes, alignment, build fingerprint).

#include <cstddef>
#include <cstdint>

#define FITFEEL_PLUGIN_ABI_VERSION 7u
#define FITFEEL_PLUGIN_HOOK_NAME "fitfeel_plugin_register"

namespace fitfeel {
class SurfaceType;
class Device;
}  // namespace fitfeel

extern "C" {

enum FitfeelPluginKind : std::uint32_t {
  kFitfeelSurfacePlugin = 1,  // factory makes a fitfeel::SurfaceType
  kFitfeelDevicePlugin = 2,   // factory makes a fitfeel::Device
};

struct FitfeelPluginEntry {
  const char* id;       // stable dotted id, e.g. "fitfeel.surface.cylindrical"
  std::uint32_t kind;   // FitfeelPluginKind
  const char* version;  // the plugin's own semantic version, e.g. "1.0.0"
  const char* summary;  // one line for `fitfeel plugins`
  // Returns a new object of the kind's type (caller owns it), or null on failure.
  void* (*factory)();
};

struct FitfeelPluginDescriptor {
  std::uint32_t abi_version;       // FITFEEL_PLUGIN_ABI_VERSION
  std::uint32_t descriptor_size;   // sizeof(FitfeelPluginDescriptor)
  std::uint32_t descriptor_align;  // alignof(FitfeelPluginDescriptor)
  std::uint32_t entry_size;        // sizeof(FitfeelPluginEntry)
  const char* build_fingerprint;   // fitfeel::BuildFingerprint() of the plugin's build
  std::uint32_t entry_count;
  const FitfeelPluginEntry* entries;
};

typedef const FitfeelPluginDescriptor* (*FitfeelPluginHook)();
}
