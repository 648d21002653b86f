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

FITFEEL_SURFACE_CONFORMANCE(Cylindrical, "surfaces/cylindrical/test/sms_scene.yaml");
