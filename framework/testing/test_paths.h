#pragma once

// The source and build trees of the test binaries, forced into every test translation unit by
// fitfeel_add_test. FITFEEL_TEST_SOURCE_DIR and FITFEEL_TEST_BUILD_DIR expand to calls into a
// small generated library (cmake/templates/test_paths.cc.in) instead of string literals, so that
// a test compiles to the same object in any checkout and a shared compiler cache serves them all.
extern "C" const char* fitfeel_test_source_dir();
extern "C" const char* fitfeel_test_build_dir();
