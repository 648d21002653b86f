#pragma once

#include <memory>
#include <type_traits>

#include "framework/core/error.h"
#include "framework/core/export.h"

namespace fitfeel {

// A surface type's `model.options`, parsed and checked once, when the scene loads
// (SurfaceType::ParseOptions), and kept in the scene's ModelSettings::options: each surface
// plugin derives its own struct from this base, and its objects read it back with OptionsAs.
// Nothing parses the options again. The base's vtable and type information live in the framework
// library, so an options object crosses the plugin boundary as a Geometry does, under the
// registry's ABI version and build fingerprint (framework/plugin/abi.h, fingerprint.h).
class FITFEEL_API SurfaceOptions {
 public:
  SurfaceOptions() = default;
  virtual ~SurfaceOptions();

 protected:
  // Copied as the derived struct only (OptionsAs), never sliced through the base.
  SurfaceOptions(const SurfaceOptions&) = default;
  SurfaceOptions& operator=(const SurfaceOptions&) = default;
};

// `options` as the surface type's own T; throws UserError when another surface type parsed them
// (settings handed to the wrong surface's objects).
template <class T>
const T& OptionsAs(const SurfaceOptions& options) {
  static_assert(std::is_base_of_v<SurfaceOptions, T>);
  if (const T* typed = dynamic_cast<const T*>(&options)) return *typed;
  throw UserError("model options parsed by another surface type");
}

// The same from ModelSettings::options, and T's defaults when it holds none (a scene without
// `model.options`, or settings made in code).
template <class T>
T OptionsAs(const std::shared_ptr<const SurfaceOptions>& options) {
  return options == nullptr ? T{} : OptionsAs<T>(*options);
}

}  // namespace fitfeel
