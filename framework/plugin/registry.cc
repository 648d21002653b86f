#include "framework/plugin/registry.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include <boost/dll/shared_library.hpp>

#include "framework/core/build_info.h"
#include "framework/core/error.h"
#include "framework/core/path_check.h"
#include "framework/device/device.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/fingerprint.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// Bounds for reading what a foreign library hands us: a garbage pointer or count must give a
// refusal, not a read of megabytes of memory.
constexpr std::uint32_t kMaxEntries = 4096;
constexpr std::size_t kMaxIdLength = 128;
constexpr std::size_t kMaxStringLength = 4096;

// A library failed a check; `reason` says what was expected and what was found.
struct Refusal {
  std::string reason;
};

[[noreturn]] void Refuse(std::string reason) { throw Refusal{std::move(reason)}; }

// Handles of every library accepted by any registry in the process. Leaked on purpose: an object
// made by a plugin may be destroyed after every registry is gone (even during static destruction),
// and its destructor is code in the library, so no library is ever closed.
void KeepLoadedForever(boost::dll::shared_library library) {
  static std::mutex mutex;
  static auto* libraries = new std::vector<boost::dll::shared_library>();
  std::lock_guard<std::mutex> lock(mutex);
  libraries->push_back(std::move(library));
}

std::string Quoted(const char* text) {
  if (text == nullptr) return "null";
  const std::size_t length = strnlen(text, kMaxStringLength);
  std::string out = "\"" + std::string(text, length);
  if (length == kMaxStringLength) out += "...";
  return out + "\"";
}

// Absolute, and canonical when it exists, so that one file reached through two folders (or a
// symlink) is recognised as already loaded.
fs::path Normalized(const fs::path& path) {
  std::error_code ec;
  fs::path out = fs::weakly_canonical(path, ec);
  if (ec) out = fs::absolute(path, ec).lexically_normal();
  return out;
}

std::vector<fs::path> EnvironmentPath() {
  std::vector<fs::path> out;
  const char* env = std::getenv("FITFEEL_PLUGIN_PATH");
  if (env == nullptr) return out;
  std::string_view rest(env);
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    const std::string_view item = rest.substr(0, colon);
    if (!item.empty()) out.emplace_back(std::string(item));
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  return out;
}

// Boost.DLL reports "...load() failed (dlerror system message: <text>): <errno text>", where the
// errno text is meaningless after dlopen; the dynamic loader's own text is what a user needs.
std::string LoaderMessage(const std::string& what) {
  static constexpr std::string_view kMarker = "dlerror system message: ";
  const std::size_t start = what.find(kMarker);
  const std::size_t end = what.rfind(')');
  if (start == std::string::npos || end == std::string::npos || end < start) return what;
  return what.substr(start + kMarker.size(), end - start - kMarker.size());
}

bool IsPluginFileName(const std::string& name) {
  return name.size() > 6 && name.compare(0, 3, "lib") == 0 &&
         name.compare(name.size() - 3, 3, ".so") == 0;
}

}  // namespace

std::string PluginKindName(std::uint32_t kind) {
  switch (kind) {
    case kFitfeelSurfacePlugin:
      return "surface";
    case kFitfeelDevicePlugin:
      return "device";
  }
  return "unknown kind " + std::to_string(kind);
}

bool IsValidPluginId(std::string_view id) {
  if (id.empty() || id.size() > kMaxIdLength) return false;
  int segments = 0;
  bool segment_start = true;
  for (const char c : id) {
    if (segment_start) {
      if (c < 'a' || c > 'z') return false;
      segment_start = false;
      ++segments;
    } else if (c == '.') {
      segment_start = true;
    } else if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) {
      return false;
    }
  }
  return !segment_start && segments >= 2;
}

std::string DescribeSearchFolder(const std::filesystem::path& folder) {
  std::string out = folder.string();
  const fs::path normal = folder.lexically_normal();
  if (normal == fs::path(BuildPluginDir()).lexically_normal()) {
    out += " (build tree)";
  } else if (normal == fs::path(InstallPluginDir()).lexically_normal()) {
    out += " (install prefix)";
  } else {
    for (const fs::path& item : EnvironmentPath()) {
      if (item.lexically_normal() == normal) {
        out += " (FITFEEL_PLUGIN_PATH)";
        break;
      }
    }
  }
  std::error_code ec;
  if (!fs::exists(folder, ec)) {
    out += " [does not exist]";
  } else if (!fs::is_directory(folder, ec)) {
    out += " [not a folder]";
  }
  return out;
}

struct PluginRegistry::Impl {
  struct Entry {
    PluginInfo info;
    void* (*factory)() = nullptr;
  };
  std::vector<Entry> entries;                             // in load order
  std::map<std::string, std::size_t, std::less<>> by_id;  // index into entries
  std::set<fs::path> loaded;                              // normalized paths of accepted libraries
  std::set<fs::path> refused;                             // normalized paths of refused libraries
  bool scanned = false;

  const Entry* Find(std::string_view id) const {
    const auto it = by_id.find(id);
    return it == by_id.end() ? nullptr : &entries[it->second];
  }

  // Checks every entry before registering any, so a refused library leaves nothing behind.
  void CheckEntries(const FitfeelPluginEntry* list, std::uint32_t count) const {
    for (std::uint32_t i = 0; i < count; ++i) {
      const FitfeelPluginEntry& e = list[i];
      const std::string where = "entry #" + std::to_string(i);
      if (e.id == nullptr) Refuse(where + ": id is null; expected a dotted lowercase id");
      if (!IsValidPluginId(std::string_view(e.id, strnlen(e.id, kMaxIdLength + 1)))) {
        Refuse(where + ": malformed id " + Quoted(e.id) +
               "; expected a stable dotted lowercase id such as fitfeel.surface.cylindrical "
               "(at least two segments of a-z, 0-9 and '_', each starting with a letter, at most " +
               std::to_string(kMaxIdLength) + " characters)");
      }
      const std::string named = where + " ('" + e.id + "')";
      if (e.kind != kFitfeelSurfacePlugin && e.kind != kFitfeelDevicePlugin) {
        Refuse(named + ": unknown kind " + std::to_string(e.kind) + "; expected " +
               std::to_string(kFitfeelSurfacePlugin) + " (surface) or " +
               std::to_string(kFitfeelDevicePlugin) + " (device)");
      }
      if (e.factory == nullptr) Refuse(named + ": factory is null; expected a function pointer");
      if (e.version == nullptr || e.version[0] == '\0') {
        Refuse(named + ": version is " + Quoted(e.version) +
               "; expected the plugin's semantic version, e.g. \"1.0.0\"");
      }
      for (std::uint32_t j = 0; j < i; ++j) {
        if (std::strcmp(list[j].id, e.id) == 0) {
          Refuse(named + ": duplicate id, already claimed by entry #" + std::to_string(j) +
                 " of the same library");
        }
      }
      if (const Entry* other = Find(e.id)) {
        Refuse(named + ": duplicate id '" + e.id + "', already provided by " +
               (other->info.library.empty() ? std::string("an in-process entry")
                                            : other->info.library.string()) +
               " (the first library on the search path keeps an id)");
      }
    }
  }

  void Register(const FitfeelPluginEntry& e, const fs::path& library) {
    Entry entry;
    entry.info.id = e.id;
    entry.info.kind = static_cast<FitfeelPluginKind>(e.kind);
    entry.info.version = std::string(e.version, strnlen(e.version, kMaxStringLength));
    if (e.summary != nullptr) {
      entry.info.summary = std::string(e.summary, strnlen(e.summary, kMaxStringLength));
    }
    entry.info.library = library;
    entry.factory = e.factory;
    by_id.emplace(entry.info.id, entries.size());
    entries.push_back(std::move(entry));
  }

  // Loads `library` and runs every check in the order of the ABI contract; throws Refusal.
  void Load(const fs::path& library) {
    if (const std::string why = WhyNotReadableFile(library); why == kDoesNotExist) {
      Refuse("no such file");
    } else if (!why.empty()) {
      Refuse(why);
    }

    boost::dll::shared_library handle;
    try {
      // RTLD_NOW: an unresolved symbol refuses the library here instead of crashing a tick later.
      // RTLD_LOCAL: one plugin's symbols never bind another's.
      handle.load(library, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local);
    } catch (const std::exception& e) {
      Refuse("cannot be loaded: " + LoaderMessage(e.what()));
    }
    if (!handle.has(FITFEEL_PLUGIN_HOOK_NAME)) {
      Refuse("no registration hook: expected an exported extern \"C\" symbol '" +
             std::string(FITFEEL_PLUGIN_HOOK_NAME) +
             "' (defined with visibility(\"default\") in the plugin's register.cc), found none");
    }
    const auto& hook = handle.get<const FitfeelPluginDescriptor*()>(FITFEEL_PLUGIN_HOOK_NAME);
    const FitfeelPluginDescriptor* d = hook();
    if (d == nullptr)
      Refuse(
          "registration hook returned a null descriptor; expected a pointer to the plugin's static "
          "FitfeelPluginDescriptor");
    if (d->abi_version != FITFEEL_PLUGIN_ABI_VERSION) {
      Refuse("plugin ABI version mismatch: expected " + std::to_string(FITFEEL_PLUGIN_ABI_VERSION) +
             ", found " + std::to_string(d->abi_version) +
             " (rebuild the plugin against this fitfeel)");
    }
    if (d->descriptor_size != sizeof(FitfeelPluginDescriptor)) {
      Refuse("descriptor size mismatch: expected sizeof(FitfeelPluginDescriptor) = " +
             std::to_string(sizeof(FitfeelPluginDescriptor)) + " bytes, found " +
             std::to_string(d->descriptor_size));
    }
    if (d->descriptor_align != alignof(FitfeelPluginDescriptor)) {
      Refuse("descriptor alignment mismatch: expected alignof(FitfeelPluginDescriptor) = " +
             std::to_string(alignof(FitfeelPluginDescriptor)) + ", found " +
             std::to_string(d->descriptor_align));
    }
    if (d->entry_size != sizeof(FitfeelPluginEntry)) {
      Refuse("entry size mismatch: expected sizeof(FitfeelPluginEntry) = " +
             std::to_string(sizeof(FitfeelPluginEntry)) + " bytes, found " +
             std::to_string(d->entry_size));
    }
    static constexpr const char* kFingerprint = FITFEEL_BUILD_FINGERPRINT;
    if (d->build_fingerprint == nullptr ||
        strncmp(d->build_fingerprint, kFingerprint, kMaxStringLength) != 0) {
      Refuse("build fingerprint mismatch: expected " + Quoted(kFingerprint) + ", found " +
             Quoted(d->build_fingerprint) +
             " (the plugin was built with another compiler, C++ library or Eigen)");
    }
    if (d->entries == nullptr) {
      Refuse("entries is null (entry_count " + std::to_string(d->entry_count) +
             "); expected an array of entries");
    }
    if (d->entry_count == 0) Refuse("entry_count is 0: the library registers nothing");
    if (d->entry_count > kMaxEntries) {
      Refuse("entry_count is " + std::to_string(d->entry_count) + "; expected at most " +
             std::to_string(kMaxEntries));
    }
    CheckEntries(d->entries, d->entry_count);
    for (std::uint32_t i = 0; i < d->entry_count; ++i) Register(d->entries[i], library);
    KeepLoadedForever(std::move(handle));
  }
};

std::vector<std::filesystem::path> PluginRegistry::DefaultSearchPath() {
  std::vector<fs::path> candidates = EnvironmentPath();
  if (!RunningFromInstall()) candidates.emplace_back(BuildPluginDir());
  candidates.emplace_back(InstallPluginDir());
  std::vector<fs::path> out;
  for (const fs::path& folder : candidates) {
    if (std::find(out.begin(), out.end(), folder) == out.end()) out.push_back(folder);
  }
  return out;
}

PluginRegistry::PluginRegistry(std::vector<std::filesystem::path> search_path)
    : search_path_(std::move(search_path)), impl_(std::make_unique<Impl>()) {}

PluginRegistry::~PluginRegistry() = default;

void PluginRegistry::LoadAll() {
  impl_->scanned = true;
  for (const fs::path& folder : search_path_) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;  // reported as searched, not as an error
    std::vector<fs::path> libraries;
    fs::directory_iterator it(folder, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
      if (IsPluginFileName(it->path().filename().string()) && it->is_regular_file(ec)) {
        libraries.push_back(it->path());
      }
    }
    if (ec) {
      refused_.push_back({folder, "cannot read plugin folder: " + ec.message()});
      continue;
    }
    // Sorted, so that which of two libraries in one folder claims an id first is reproducible.
    std::sort(libraries.begin(), libraries.end());
    for (const fs::path& library : libraries) {
      const fs::path normal = Normalized(library);
      if (impl_->loaded.count(normal) != 0 || impl_->refused.count(normal) != 0) continue;
      try {
        impl_->Load(normal);
        impl_->loaded.insert(normal);
      } catch (const Refusal& refusal) {
        impl_->refused.insert(normal);
        refused_.push_back({normal, refusal.reason});
      }
    }
  }
}

void PluginRegistry::LoadLibrary(const std::filesystem::path& library) {
  const fs::path normal = Normalized(library);
  if (impl_->loaded.count(normal) != 0) return;
  try {
    impl_->Load(normal);
    impl_->loaded.insert(normal);
  } catch (const Refusal& refusal) {
    throw PluginError("plugin library " + normal.string() + " refused: " + refusal.reason);
  }
}

void PluginRegistry::AddEntry(const FitfeelPluginEntry& entry) {
  try {
    impl_->CheckEntries(&entry, 1);
  } catch (const Refusal& refusal) {
    throw PluginError("in-process plugin entry refused: " + refusal.reason);
  }
  impl_->Register(entry, fs::path());
}

std::vector<PluginInfo> PluginRegistry::plugins() const {
  std::vector<PluginInfo> out;
  out.reserve(impl_->entries.size());
  for (const auto& entry : impl_->entries) out.push_back(entry.info);
  return out;
}

bool PluginRegistry::Has(std::string_view id) const { return impl_->Find(id) != nullptr; }

namespace {

std::string ListFound(const std::vector<PluginInfo>& plugins) {
  if (plugins.empty()) return "found: no plugins\n";
  std::string out = "found:\n";
  for (const PluginInfo& p : plugins) {
    out += "  " + p.id + " (" + PluginKindName(p.kind) + ", " +
           (p.library.empty() ? std::string("in-process") : p.library.string()) + ")\n";
  }
  return out;
}

}  // namespace

void* PluginRegistry::Make(std::string_view id, std::uint32_t kind) const {
  const Impl::Entry* entry = impl_->Find(id);
  const std::string wanted = PluginKindName(kind);
  if (entry == nullptr) {
    std::string message = "no " + wanted + " plugin with id '" + std::string(id) + "'\n";
    message += "searched, in order:\n";
    for (const fs::path& folder : search_path_)
      message += "  " + DescribeSearchFolder(folder) + "\n";
    if (!impl_->scanned)
      message += "  (the search path has not been scanned: LoadAll() was not called)\n";
    message += ListFound(plugins());
    if (!refused_.empty()) {
      message += "refused:\n";
      for (const RefusedLibrary& r : refused_) {
        message += "  " + r.library.string() + ": " + r.reason + "\n";
      }
    }
    message.pop_back();
    throw PluginError(message);
  }
  const std::string from =
      entry->info.library.empty() ? std::string("in-process") : entry->info.library.string();
  if (entry->info.kind != kind) {
    std::string message = "plugin '" + entry->info.id + "' (" + from + ") is a " +
                          PluginKindName(entry->info.kind) + " plugin, not a " + wanted +
                          " plugin; " + wanted + " plugins found:";
    bool any = false;
    for (const auto& e : impl_->entries) {
      if (e.info.kind == kind) {
        message += " " + e.info.id;
        any = true;
      }
    }
    if (!any) message += " none";
    throw PluginError(message);
  }
  void* object = nullptr;
  try {
    object = entry->factory();
  } catch (const UserError&) {
    throw;
  } catch (const std::exception& e) {
    throw PluginError("plugin '" + entry->info.id + "' (" + from +
                      ") failed to make its object: " + e.what());
  }
  if (object == nullptr) {
    throw PluginError("plugin '" + entry->info.id + "' (" + from +
                      ") failed to make its object: its factory returned null");
  }
  return object;
}

std::shared_ptr<SurfaceType> PluginRegistry::MakeSurface(std::string_view id) const {
  // The factory converted the object to SurfaceType* before returning void* (plugin_entry.h), so
  // this cast restores exactly that pointer; deleting through it runs the plugin's destructor,
  // whose code stays loaded because no library is ever closed.
  return std::shared_ptr<SurfaceType>(static_cast<SurfaceType*>(Make(id, kFitfeelSurfacePlugin)));
}

std::shared_ptr<Device> PluginRegistry::MakeDevice(std::string_view id) const {
  return std::shared_ptr<Device>(static_cast<Device*>(Make(id, kFitfeelDevicePlugin)));
}

}  // namespace fitfeel
