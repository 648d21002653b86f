// The framework's conformance suite on test/conformance.yaml. Under tests/ only: the plugin is
// built into test-plugins/example_slide, which joins the search path of the suite's registry (a
// surface under surfaces/ needs only FITFEEL_SURFACE_CONFORMANCE(Name, scenario)).
#include <string>

#include "framework/conformance/surface_conformance.h"

FITFEEL_SURFACE_CONFORMANCE_WITH_PLUGINS(ExampleSlide, "tests/example_slide/test/conformance.yaml",
                                         std::string(FITFEEL_TEST_BUILD_DIR) +
                                             "/test-plugins/example_slide");
