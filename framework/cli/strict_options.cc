#include "framework/cli/strict_options.h"

#include <optional>
#include <stdexcept>
#include <system_error>

#include "framework/core/error.h"
#include "framework/core/os_reason.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void Refuse(const std::string& option, const std::string& expected,
                         const std::string& found) {
  throw OptionError(option + ": expected " + expected + ", found " + found);
}

std::string Quoted(const std::string& text) { return text.empty() ? "nothing" : "'" + text + "'"; }

// The status of an existing path, or nullopt when nothing is there. A path that cannot even be
// looked at (a symlink loop, a folder without access) is refused in the OS's words.
std::optional<fs::file_status> Existing(const std::string& option, const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return std::nullopt;
  if (ec) {
    Refuse(option, "a path to write", "'" + path.string() + "', which cannot be opened: " +
                                          OsReason(ec));
  }
  return status;
}

void CheckParent(const std::string& option, const fs::path& path) {
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (const auto status = Existing(option, parent); status && !fs::is_directory(*status)) {
    Refuse(option, "a path inside a folder", "'" + path.string() + "' ('" + parent.string() +
                                                 "' is not a folder)");
  }
}

// "--seed" of "-s,--seed": the name a refusal gives.
std::string LongName(const std::string& name) {
  const std::size_t comma = name.rfind(',');
  return name.substr(comma == std::string::npos ? 0 : comma + 1);
}

}  // namespace

CLI::Option* AddIntegerOption(CLI::App* cmd, const std::string& name, long min, long max,
                              std::function<void(long)> set, const std::string& help) {
  const std::string option = LongName(name);
  return cmd->add_option_function<std::string>(
      name,
      [option, min, max, set](const std::string& text) {
        const std::optional<long> value = ParseInteger(text, min, max);
        if (!value) Refuse(option, DescribeIntegerRange(min, max), Quoted(text));
        set(*value);
      },
      help);
}

CLI::Option* AddSeedOption(CLI::App* cmd, const std::string& name,
                           std::function<void(std::uint64_t)> set, const std::string& help) {
  return cmd->add_option_function<std::string>(
      name,
      [option = LongName(name), set](const std::string& text) {
        const std::optional<std::uint64_t> value = ParseSeed(text);
        if (!value) Refuse(option, kSeedRange, Quoted(text));
        set(*value);
      },
      help);
}

CLI::Option* AddQuantityOption(CLI::App* cmd, const std::string& name, Dimension dimension,
                               double min, double max, std::function<void(double)> set,
                               const std::string& help) {
  const std::string option = LongName(name);
  return cmd->add_option_function<std::string>(
      name,
      [option, dimension, min, max, set](const std::string& text) {
        const std::string expected = DescribeDimension(dimension) + " in [" +
                                     FormatQuantity(min, dimension) + ", " +
                                     FormatQuantity(max, dimension) + "]";
        double value = 0.0;
        try {
          value = ParseQuantity(text, dimension);
        } catch (const std::invalid_argument& e) {
          Refuse(option, expected, Quoted(text) + " (" + e.what() + ")");
        }
        if (!(value >= min && value <= max)) Refuse(option, expected, Quoted(text));
        set(value);
      },
      help);
}

void CheckOutputFile(const std::string& option, const fs::path& file) {
  if (file.empty()) Refuse(option, "an output file", "nothing");
  if (const auto status = Existing(option, file); status && !fs::is_regular_file(*status)) {
    Refuse(option, "a regular file to write (or a new one)",
           "'" + file.string() + "', which is " +
               (fs::is_directory(*status) ? "a folder" : "a device, pipe or socket"));
  }
  CheckParent(option, file);
}

void CheckOutputFolder(const std::string& option, const fs::path& folder) {
  if (folder.empty()) Refuse(option, "an output folder", "nothing");
  if (const auto status = Existing(option, folder); status && !fs::is_directory(*status)) {
    Refuse(option, "a folder to write into (or a new one)",
           "'" + folder.string() + "', which is not a folder");
  }
  CheckParent(option, folder);
}

}  // namespace fitfeel::cli
