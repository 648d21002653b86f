// The framework's conformance suite for this plugin, on test/sms_scene.yaml (paper Table 2). The
// scene's device is the registry's test device: its folder joins the search path of the suite's
// registry.
#include <string>

#include "framework/conformance/surface_conformance.h"

FITFEEL_SURFACE_CONFORMANCE_WITH_PLUGINS(Cylindrical, "surfaces/cylindrical/test/sms_scene.yaml",
                                         std::string(FITFEEL_TEST_BUILD_DIR) +
                                             "/test-plugins/good");
