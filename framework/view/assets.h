#pragma once

#include <string_view>

#include "framework/core/export.h"

namespace fitfeel::view {

// One file the viewer serves: its URL path, content type and bytes. The set is fixed at build
// time (the page's own files from framework/view/web and three.js from Debian's libjs-three,
// embedded by framework/view/embed_assets.cc), so no URL ever reaches the file system.
struct Asset {
  std::string_view path;
  std::string_view content_type;
  std::string_view body;
};

// The asset served at exactly `path` ("/" is the page), or null.
FITFEEL_API const Asset* FindAsset(std::string_view path);

}  // namespace fitfeel::view
