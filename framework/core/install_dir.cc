#include <dlfcn.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "framework/core/build_info.h"

namespace fitfeel {

namespace {

// `relative` from the folder of the loaded framework library, or empty when it is no folder.
std::string BesideLibrary(const std::filesystem::path& relative) {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&BesideLibrary), &info) != 0 && info.dli_fname != nullptr) {
    const std::filesystem::path beside =
        std::filesystem::path(info.dli_fname).parent_path() / relative;
    std::error_code ec;
    if (std::filesystem::is_directory(beside, ec)) return beside.lexically_normal().string();
  }
  return std::string();
}

// lib/fitfeel/plugins beside the loaded framework library, or empty when there is none.
const std::string& PluginsBesideLibrary() {
  static const std::string dir = BesideLibrary(std::filesystem::path("fitfeel") / "plugins");
  return dir;
}

}  // namespace

const char* InstallPluginDir() {
  return RunningFromInstall() ? PluginsBesideLibrary().c_str() : ConfiguredInstallPluginDir();
}

bool RunningFromInstall() { return !PluginsBesideLibrary().empty(); }

const std::string& ShippedDataDir() {
  static const std::string dir =
      RunningFromInstall() ? BesideLibrary(std::filesystem::path("..") / "share" / "fitfeel")
                           : std::string(BuildSourceDir());
  return dir;
}

}  // namespace fitfeel
