#include <dlfcn.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "framework/core/build_info.h"

namespace fitfeel {

namespace {

// lib/fitfeel/plugins beside the loaded framework library, or empty when there is none.
const std::string& PluginsBesideLibrary() {
  static const std::string dir = [] {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&PluginsBesideLibrary), &info) != 0 &&
        info.dli_fname != nullptr) {
      const std::filesystem::path beside =
          std::filesystem::path(info.dli_fname).parent_path() / "fitfeel" / "plugins";
      std::error_code ec;
      if (std::filesystem::is_directory(beside, ec)) return beside.lexically_normal().string();
    }
    return std::string();
  }();
  return dir;
}

}  // namespace

const char* InstallPluginDir() {
  return RunningFromInstall() ? PluginsBesideLibrary().c_str() : ConfiguredInstallPluginDir();
}

bool RunningFromInstall() { return !PluginsBesideLibrary().empty(); }

}  // namespace fitfeel
