#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "framework/core/error.h"
#include "framework/core/quantity.h"

namespace fitfeel::cli {

// A command-line value refused by the checks below; main prints it with the command's usage line.
class OptionError : public UserError {
 public:
  using UserError::UserError;
};

// Numeric command-line options read as text and parsed with the scenario keys' rules
// (ParseInteger, ParseSeed, ParseQuantity), so that `--seed -1`, `--seed ''` and a seed past
// 2^64 - 1 are refused as run.seed is, never clamped or ignored. A refusal throws OptionError
// naming the option: "--seed: expected an integer in [0, 18446744073709551615], found '-1'" (exit
// code 2).
CLI::Option* AddIntegerOption(CLI::App* cmd, const std::string& name, long min, long max,
                              std::function<void(long)> set, const std::string& help);
// A seed (ParseSeed: every 64-bit value, a study pair's included).
CLI::Option* AddSeedOption(CLI::App* cmd, const std::string& name,
                           std::function<void(std::uint64_t)> set, const std::string& help);
// A quantity of `dimension` (a dimensionless one is a bare number) in [min, max].
CLI::Option* AddQuantityOption(CLI::App* cmd, const std::string& name, Dimension dimension,
                               double min, double max, std::function<void(double)> set,
                               const std::string& help);

// Output paths: an existing path must be a regular file (`file`) or a folder (`folder`); a device,
// FIFO or socket is refused (`-o /dev/null` would otherwise write /dev/null.png beside it), as is
// a path whose parent exists but is not a folder. Throws OptionError naming the option.
void CheckOutputFile(const std::string& option, const std::filesystem::path& file);
void CheckOutputFolder(const std::string& option, const std::filesystem::path& folder);

}  // namespace fitfeel::cli
