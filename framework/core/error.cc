#include "framework/core/error.h"

#include <utility>

namespace fitfeel {
namespace {

std::string FormatScenarioError(const SourceLocation& where, const std::string& key_path,
                                const std::string& expected, const std::string& found) {
  std::string out = where.file;
  if (where.line > 0) {
    out += ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
  }
  out += ": ";
  if (!key_path.empty()) out += key_path + ": ";
  out += "expected " + expected + ", found " + found;
  return out;
}

}  // namespace

UserError::~UserError() = default;
PluginError::~PluginError() = default;
UnsupportedError::~UnsupportedError() = default;

ScenarioError::ScenarioError(SourceLocation where, std::string key_path, std::string expected,
                             std::string found)
    : UserError(FormatScenarioError(where, key_path, expected, found)),
      where_(std::move(where)),
      key_path_(std::move(key_path)),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

ScenarioError::~ScenarioError() = default;

}  // namespace fitfeel
