// The framework's conformance suite on test/conformance.yaml. The scene's device is the registry's
// test device (the SMS and the contact model do not depend on it): its folder joins the search
// path of the suite's registry.
#include <string>

#include "framework/conformance/surface_conformance.h"

FITFEEL_SURFACE_CONFORMANCE_WITH_PLUGINS(Conical, "surfaces/conical/test/conformance.yaml",
                                         std::string(FITFEEL_TEST_BUILD_DIR) +
                                             "/test-plugins/good");
