#pragma once

// For libFuzzer targets whose code under test reads a file: the input written to a file of the
// process's own (one per target and process, rewritten on every call).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace fitfeel::test_support {

inline std::filesystem::path WriteFuzzInput(const std::string& name, const std::uint8_t* data,
                                            std::size_t size) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("fitfeel-fuzz-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace fitfeel::test_support
