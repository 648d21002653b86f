#pragma once

// Helpers of the runtime's output tests: a fresh temporary folder and a file's lines.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fitfeel::testing {

// <temp>/fitfeel-<group>-<name>-<pid>, removed if a previous run left it (not created).
inline std::filesystem::path FreshDir(const std::string& group, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("fitfeel-" + group + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

inline std::vector<std::string> Lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace fitfeel::testing
