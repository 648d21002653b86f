#pragma once

#include <string>

#include "framework/core/export.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

// A short human-readable account of a loaded scene, one aspect per line (parts with their size
// limits in um, form, texture, material; law and model settings; device; run), for
// `fitfeel validate` and run banners. Ends with a newline.
FITFEEL_API std::string DescribeScene(const Scene& scene);

}  // namespace fitfeel
