#pragma once

// The plugins this build tree built, loaded once per test process: the end-to-end tests that load
// shipped scenes read them from the build folder itself, never from an installed copy or the
// environment's plugin path (PluginRegistry::DefaultSearchPath).
#include <filesystem>

#include "framework/plugin/registry.h"

namespace fitfeel::test_support {

inline const PluginRegistry& BuildTreePlugins() {
  static const PluginRegistry* registry = [] {
    auto* r = new PluginRegistry({std::filesystem::path(FITFEEL_TEST_BUILD_DIR) / "plugins"});
    r->LoadAll();
    return r;
  }();
  return *registry;
}

}  // namespace fitfeel::test_support
