#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace fitfeel::test_support {

// The build tree: FITFEEL_BUILD_DIR, else two levels above the running test binary.
inline std::filesystem::path BuildDir() {
  if (const char* dir = std::getenv("FITFEEL_BUILD_DIR")) return std::filesystem::path(dir);
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self.parent_path().parent_path();
}

// The folder of one deliberately broken (or good) test plugin (framework/plugin/test/cases).
inline std::filesystem::path CaseDir(const std::string& name) {
  return BuildDir() / "test-plugins" / name;
}

}  // namespace fitfeel::test_support
