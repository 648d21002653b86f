#pragma once

// What a plugin's register.cc includes to describe itself. It declares the registration hook with
// the exact signature and default visibility the loader expects (so a typo in the signature is a
// compile error, not a refused library), and builds the descriptor and its entries at compile time:
//
//   #include "framework/plugin/plugin_entry.h"
//   #include "surfaces/cylindrical/cylindrical_surface.h"
//
//   namespace {
//   constexpr FitfeelPluginEntry kEntries[] = {
//       fitfeel::plugin::SurfaceEntry<fitfeel::cylindrical::CylindricalSurface>(
//           "fitfeel.surface.cylindrical", "1.0.0", "Shaft in bushing, pin in hole (the paper)"),
//   };
//   constexpr FitfeelPluginDescriptor kDescriptor = fitfeel::plugin::MakeDescriptor(kEntries);
//   }  // namespace
//
//   extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
//   fitfeel_plugin_register() {
//     return &kDescriptor;
//   }
//
// Everything else in a plugin stays hidden (the project builds with -fvisibility=hidden).

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "framework/plugin/abi.h"
#include "framework/plugin/fingerprint.h"

// The one symbol a plugin library exports. Declared here so that its definition in register.cc
// must match this signature and inherits default visibility.
extern "C" __attribute__((visibility("default"))) const FitfeelPluginDescriptor*
fitfeel_plugin_register();

namespace fitfeel::plugin {

// Factories. The loader casts the returned void* back to the kind's base class (SurfaceType* or
// Device*), so the object must be converted to that base *before* it becomes void*: with multiple
// or virtual inheritance T* and Base* differ, and a direct T* -> void* -> Base* would be wrong.
// Exceptions from T's constructor propagate to the loader, which reports them as PluginError.
template <class T>
void* MakeSurfaceObject() {
  static_assert(std::is_base_of_v<SurfaceType, T>,
                "a surface plugin must make a fitfeel::SurfaceType");
  SurfaceType* base = new T();
  return static_cast<void*>(base);
}

template <class T>
void* MakeDeviceObject() {
  static_assert(std::is_base_of_v<Device, T>, "a device plugin must make a fitfeel::Device");
  Device* base = new T();
  return static_cast<void*>(base);
}

// One entry of the descriptor. `id` is a stable dotted lowercase id (fitfeel.surface.cylindrical),
// `version` the plugin's own semantic version, `summary` one line for `fitfeel plugins`. The
// strings must have static storage duration (string literals).
template <class T>
constexpr FitfeelPluginEntry SurfaceEntry(const char* id, const char* version,
                                          const char* summary) {
  return FitfeelPluginEntry{id, kFitfeelSurfacePlugin, version, summary, &MakeSurfaceObject<T>};
}

template <class T>
constexpr FitfeelPluginEntry DeviceEntry(const char* id, const char* version, const char* summary) {
  return FitfeelPluginEntry{id, kFitfeelDevicePlugin, version, summary, &MakeDeviceObject<T>};
}

// The descriptor of a plugin built now, with these headers and this compiler: ABI version, sizes,
// alignment and build fingerprint are filled in here, never by hand. `entries` must have static
// storage duration (a namespace-scope constexpr array).
template <std::size_t N>
constexpr FitfeelPluginDescriptor MakeDescriptor(const FitfeelPluginEntry (&entries)[N]) {
  return FitfeelPluginDescriptor{
      FITFEEL_PLUGIN_ABI_VERSION,
      static_cast<std::uint32_t>(sizeof(FitfeelPluginDescriptor)),
      static_cast<std::uint32_t>(alignof(FitfeelPluginDescriptor)),
      static_cast<std::uint32_t>(sizeof(FitfeelPluginEntry)),
      FITFEEL_BUILD_FINGERPRINT,
      static_cast<std::uint32_t>(N),
      entries,
  };
}

}  // namespace fitfeel::plugin

// Shorthands for a factory pointer with the right base-class cast, for hand-written entries.
#define FITFEEL_SURFACE_FACTORY(Type) (&::fitfeel::plugin::MakeSurfaceObject<Type>)
#define FITFEEL_DEVICE_FACTORY(Type) (&::fitfeel::plugin::MakeDeviceObject<Type>)
