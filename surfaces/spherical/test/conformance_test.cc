// The framework's conformance suite on test/conformance.yaml. The scene's device is the registry's
// test device (the SMS and the contact model do not depend on it): its folder joins the plugin
// search path before the suite builds its registry.
#include <cstdlib>
#include <string>

#include "framework/conformance/surface_conformance.h"

namespace {
const bool kTestDeviceOnPath = [] {
  const std::string path = std::string(FITFEEL_TEST_BUILD_DIR) + "/test-plugins/good";
  return ::setenv("FITFEEL_PLUGIN_PATH", path.c_str(), 1) == 0;
}();
}  // namespace

FITFEEL_SURFACE_CONFORMANCE(Spherical, "surfaces/spherical/test/conformance.yaml");
