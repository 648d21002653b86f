#pragma once

#include <string>

#include "framework/core/export.h"

namespace fitfeel {

// Where this build keeps its plugins, and where an install puts them. They live in one generated
// source file (cmake/templates/build_info.cc.in) rather than in compile definitions, so that every
// other translation unit compiles to the same object in any checkout (a shared compiler cache
// then serves every work tree).
FITFEEL_API const char* BuildPluginDir();
// The installed plugin folder: lib/fitfeel/plugins beside the installed framework library, found
// from where the library was loaded (an install prefix moved or chosen at `cmake --install
// --prefix` still finds its plugins); the configured prefix's folder when that does not exist
// (the build tree).
FITFEEL_API const char* InstallPluginDir();
// True when this framework library is an installed one (lib/fitfeel/plugins beside it): the
// build tree's plugins are then not searched, whatever tree the library was built in.
FITFEEL_API bool RunningFromInstall();
// CMAKE_INSTALL_PREFIX/lib/fitfeel/plugins as configured (generated).
const char* ConfiguredInstallPluginDir();
// The source tree this build was configured from (generated).
const char* BuildSourceDir();
// Where the shipped scenarios (scenarios/) and chart scripts live: an installed library's
// share/fitfeel beside its lib/ (found from where the library was loaded, like its plugins; empty
// when the install has none), the build's source tree otherwise. An install never reads a source
// tree.
FITFEEL_API const std::string& ShippedDataDir();

}  // namespace fitfeel
