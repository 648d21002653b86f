#pragma once

// The source and build trees as the tests see them (test_paths.h), as paths.
#include <filesystem>
#include <string>

namespace fitfeel::test_support {

inline const std::filesystem::path kSourceTree = fitfeel_test_source_dir();
inline const std::filesystem::path kBuildTree = fitfeel_test_build_dir();

// A scenario shipped in scenarios/, as `fitfeel run` loads it from the source tree.
inline std::filesystem::path ShippedScenario(const std::string& file_name) {
  return kSourceTree / "scenarios" / file_name;
}

}  // namespace fitfeel::test_support
