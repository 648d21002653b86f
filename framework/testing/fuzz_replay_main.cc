// Replays the libFuzzer targets' corpora without libFuzzer, so that `make test` (GCC, no clang)
// runs every kept input through its target's checks: `fitfeel_fuzz_replay TARGET FILE_OR_FOLDER...`
// sends each file (a folder's regular files, walked in name order) once through that target's
// LLVMFuzzerTestOneInput. Every target is linked in, each under its name (fuzz_targets.h). A
// finding is what it is under libFuzzer: the target aborts, or an exception escapes
// (std::terminate).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "framework/testing/fuzz_targets.h"

namespace fitfeel::test_support {
namespace {

std::map<std::string, FuzzTarget>& Targets() {
  static std::map<std::string, FuzzTarget> targets;
  return targets;
}

}  // namespace

bool RegisterFuzzTarget(const char* name, FuzzTarget target) {
  Targets().emplace(name, target);
  return true;
}

}  // namespace fitfeel::test_support

namespace {

std::vector<std::filesystem::path> FilesOf(const std::filesystem::path& argument) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(argument)) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(argument)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
  } else if (std::filesystem::is_regular_file(argument)) {
    files.push_back(argument);
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  const auto& targets = fitfeel::test_support::Targets();
  const auto target = argc >= 2 ? targets.find(argv[1]) : targets.end();
  if (argc < 3 || target == targets.end()) {
    std::fprintf(stderr, "usage: %s TARGET FILE_OR_FOLDER...\ntargets:", argv[0]);
    for (const auto& [name, entry] : targets) std::fprintf(stderr, " %s", name.c_str());
    std::fprintf(stderr, "\n");
    return 2;
  }
  std::size_t replayed = 0;
  for (int i = 2; i < argc; ++i) {
    const std::vector<std::filesystem::path> files = FilesOf(argv[i]);
    // A corpus that went missing would make the replay pass having checked nothing.
    if (files.empty()) {
      std::fprintf(stderr, "%s: no input files in %s\n", argv[0], argv[i]);
      return 1;
    }
    for (const auto& file : files) {
      std::ifstream in(file, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::printf("replay %s (%zu bytes)\n", file.c_str(), bytes.size());
      std::fflush(stdout);
      target->second(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  std::printf("%s: %zu inputs replayed, no finding\n", argv[1], replayed);
  return 0;
}
