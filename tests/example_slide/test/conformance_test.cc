// The framework's conformance suite on test/conformance.yaml. Under tests/ only: the plugin is
// built into test-plugins/example_slide, which joins the search path before the suite builds
// its registry (a surface under surfaces/ needs neither this nor the includes).
#include <cstdlib>
#include <string>

#include "framework/conformance/surface_conformance.h"

namespace {
const bool kPluginOnPath = [] {
  const std::string path = std::string(FITFEEL_TEST_BUILD_DIR) + "/test-plugins/example_slide";
  return ::setenv("FITFEEL_PLUGIN_PATH", path.c_str(), 1) == 0;
}();
}  // namespace

FITFEEL_SURFACE_CONFORMANCE(ExampleSlide, "tests/example_slide/test/conformance.yaml");
