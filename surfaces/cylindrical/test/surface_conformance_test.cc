// The framework's conformance suite for this plugin, on test/sms_scene.yaml (paper Table 2). The
// scene's device is the registry's test device: its folder joins the plugin search path before
// the suite builds its registry.
#include <cstdlib>
#include <string>

#include "framework/conformance/surface_conformance.h"

namespace {
const bool kTestDeviceOnPath = [] {
  const std::string path = std::string(FITFEEL_TEST_BUILD_DIR) + "/test-plugins/good";
  return ::setenv("FITFEEL_PLUGIN_PATH", path.c_str(), 1) == 0;
}();
}  // namespace

// The macro replaces the global operator new (to count allocations in the tick), so it is expanded
// at global scope, with the suite's names brought in.
// GCC 12 flags the macro's free() in the replaced operator delete as mismatched with `new` once
// both are inlined, although the replaced operator new allocates with malloc: a false positive.
using namespace fitfeel::conformance;  // NOLINT(build/namespaces)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
FITFEEL_SURFACE_CONFORMANCE(Cylindrical, "surfaces/cylindrical/test/sms_scene.yaml");
#pragma GCC diagnostic pop
