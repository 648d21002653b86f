#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/export.h"
#include "framework/plugin/abi.h"

namespace fitfeel {

class SurfaceType;
class Device;

// One registered entry, as `fitfeel plugins` lists it.
struct PluginInfo {
  std::string id;
  FitfeelPluginKind kind = kFitfeelSurfacePlugin;
  std::string version;
  std::string summary;
  std::filesystem::path library;  // empty for entries registered in-process
};

// A library that was found but refused, and why (wrong ABI, no hook, duplicate id, ...).
struct RefusedLibrary {
  std::filesystem::path library;
  std::string reason;
};

// Finds plugin libraries, checks their descriptor (ABI version, sizes, alignment, fingerprint)
// before using anything in them, and makes objects by stable dotted id. Libraries are never
// unloaded, so no object can outlive its code.
class FITFEEL_API PluginRegistry {
 public:
  // FITFEEL_PLUGIN_PATH (colon-separated), then the build tree's plugin folder, then the install
  // prefix's; folders that do not exist are kept (they are reported as searched).
  static std::vector<std::filesystem::path> DefaultSearchPath();

  explicit PluginRegistry(std::vector<std::filesystem::path> search_path = DefaultSearchPath());
  ~PluginRegistry();
  PluginRegistry(const PluginRegistry&) = delete;
  PluginRegistry& operator=(const PluginRegistry&) = delete;

  // Scans every folder of the search path for lib*.so and loads each; a library that fails its
  // checks is recorded in refused() and skipped; the first library to claim an id keeps it.
  void LoadAll();
  // Loads one library; throws PluginError saying exactly what is wrong with it.
  void LoadLibrary(const std::filesystem::path& library);
  // Registers an in-process entry (tests, built-ins); throws PluginError on a duplicate id.
  void AddEntry(const FitfeelPluginEntry& entry);

  const std::vector<std::filesystem::path>& search_path() const { return search_path_; }
  std::vector<PluginInfo> plugins() const;
  const std::vector<RefusedLibrary>& refused() const { return refused_; }
  bool Has(std::string_view id) const;

  // Throw PluginError naming the id, the kind expected, every folder searched, the ids found and
  // the refused libraries when `id` is not a loaded entry of that kind.
  std::shared_ptr<SurfaceType> MakeSurface(std::string_view id) const;
  std::shared_ptr<Device> MakeDevice(std::string_view id) const;

 private:
  struct Impl;
  std::vector<std::filesystem::path> search_path_;
  std::vector<RefusedLibrary> refused_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fitfeel
