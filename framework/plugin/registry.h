#pragma once

#include <cstdint>
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

// "surface", "device", or "unknown kind N".
FITFEEL_API std::string PluginKindName(std::uint32_t kind);

// True for a stable dotted lowercase id: at least two dot-separated segments, each starting with a
// letter and holding only a-z, 0-9 and '_' (fitfeel.surface.cylindrical, fitfeel.device.simulated).
FITFEEL_API bool IsValidPluginId(std::string_view id);

// One search folder as messages and `fitfeel plugins` show it: the path, where it comes from
// ("(FITFEEL_PLUGIN_PATH)", "(build tree)", "(install prefix)") and "[does not exist]" if absent.
FITFEEL_API std::string DescribeSearchFolder(const std::filesystem::path& folder);

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
  // Loads one library; throws PluginError naming the library and exactly what is wrong with it
  // (expected vs found). Loading a library this registry already accepted is a no-op.
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
  // Finds `id`, checks its kind and calls its factory; throws PluginError.
  void* Make(std::string_view id, std::uint32_t kind) const;

  struct Impl;
  std::vector<std::filesystem::path> search_path_;
  std::vector<RefusedLibrary> refused_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fitfeel
