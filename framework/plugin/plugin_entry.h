#pragma once

// What a plugin's register.cc includes to describe itself. One macro line builds the descriptor and
// its entries at compile time and defines the registration hook with the exact signature and
// default visibility the loader expects (so a typo is a compile error, not a refused library):
//
//   #include "framework/plugin/plugin_entry.h"
//   #include "surfaces/conical/conical_surface.h"
//
//   FITFEEL_REGISTER_SURFACE(fitfeel::conical::ConicalSurface, "fitfeel.surface.conical", "1.0.0",
//                            "Taper pin in a taper-reamed hole (ISO 2339 1:50)");
//
// FITFEEL_REGISTER_DEVICE is the same for a device. A library offering several objects lists their
// entries: FITFEEL_REGISTER_PLUGIN(SurfaceEntry<A>(...), DeviceEntry<B>(...)). Everything else in a
// plugin stays hidden (the project builds with -fvisibility=hidden).

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

// Defines the descriptor of this plugin from its entries (FitfeelPluginEntry values, usually
// fitfeel::plugin::SurfaceEntry<T>(...) or DeviceEntry<T>(...)) and the hook that returns it. Use it
// once, at namespace scope, in the plugin's register.cc.
#define FITFEEL_REGISTER_PLUGIN(...)                                                    \
  namespace {                                                                           \
  constexpr FitfeelPluginEntry kFitfeelPluginEntries[] = {__VA_ARGS__};                 \
  constexpr FitfeelPluginDescriptor kFitfeelPluginDescriptor =                          \
      ::fitfeel::plugin::MakeDescriptor(kFitfeelPluginEntries);                         \
  }                                                                                     \
  extern "C" const FitfeelPluginDescriptor* fitfeel_plugin_register() {                 \
    return &kFitfeelPluginDescriptor;                                                   \
  }                                                                                     \
  static_assert(true, "a registration ends with a semicolon")

// A plugin that makes one surface type T (derived from fitfeel::SurfaceType).
#define FITFEEL_REGISTER_SURFACE(T, id, version, summary) \
  FITFEEL_REGISTER_PLUGIN(::fitfeel::plugin::SurfaceEntry<T>(id, version, summary))

// A plugin that makes one device T (derived from fitfeel::Device).
#define FITFEEL_REGISTER_DEVICE(T, id, version, summary) \
  FITFEEL_REGISTER_PLUGIN(::fitfeel::plugin::DeviceEntry<T>(id, version, summary))

// Shorthands for a factory pointer with the right base-class cast, for the hand-written entries of
// the deliberately broken test plugins (tests/plugins).
#define FITFEEL_SURFACE_FACTORY(Type) (&::fitfeel::plugin::MakeSurfaceObject<Type>)
#define FITFEEL_DEVICE_FACTORY(Type) (&::fitfeel::plugin::MakeDeviceObject<Type>)
