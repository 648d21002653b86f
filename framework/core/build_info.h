#pragma once

#include "framework/core/export.h"

namespace fitfeel {

// Where this build keeps its plugins, and where an install puts them. They live in one generated
// source file (cmake/templates/build_info.cc.in) rather than in compile definitions, so that every
// other translation unit compiles to the same object in any checkout (a shared compiler cache
// then serves every work tree).
FITFEEL_API const char* BuildPluginDir();
FITFEEL_API const char* InstallPluginDir();

}  // namespace fitfeel
