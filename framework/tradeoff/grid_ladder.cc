#include "framework/tradeoff/grid_ladder.h"

#include <charconv>

#include "framework/core/error.h"

namespace fitfeel::tradeoff {
namespace {

int ParsePositive(std::string_view digits, std::string_view item) {
  int value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || value <= 0) {
    throw UserError("tradeoff: --resolutions item '" + std::string(item) +
                    "': expected ROWSxCOLUMNS with positive integers (e.g. 40x360) or 'auto'");
  }
  return value;
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::vector<Resolution> DefaultLadder() {
  return {{8, 36}, {10, 72}, {20, 90}, {20, 180}, {40, 180}, {40, 360}, {80, 720}, {160, 1440}};
}

std::string Label(const Resolution& resolution) {
  if (resolution.is_auto()) return "auto";
  return std::to_string(resolution.rows) + "x" + std::to_string(resolution.columns);
}

std::vector<Resolution> ParseLadder(std::string_view text) {
  std::vector<Resolution> ladder;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item = Trim(text.substr(start, comma - start));
    start = comma + 1;
    if (item.empty()) {
      throw UserError("tradeoff: --resolutions '" + std::string(text) + "' has an empty item");
    }
    Resolution r;
    if (item != "auto") {
      const std::size_t x = item.find_first_of("xX");
      if (x == std::string_view::npos) {
        throw UserError("tradeoff: --resolutions item '" + std::string(item) +
                        "': expected ROWSxCOLUMNS (e.g. 40x360) or 'auto'");
      }
      r.rows = ParsePositive(item.substr(0, x), item);
      r.columns = ParsePositive(item.substr(x + 1), item);
      if (r.columns % 2 != 0) {
        throw UserError("tradeoff: --resolutions item '" + std::string(item) +
                        "': the number of columns must be even (two-point sizes pair opposite "
                        "columns)");
      }
      if (static_cast<long>(r.rows) * r.columns > kMaxCellsPerPart) {
        throw UserError("tradeoff: --resolutions item '" + std::string(item) + "' has more than " +
                        std::to_string(kMaxCellsPerPart) + " cells per part");
      }
    }
    for (const Resolution& seen : ladder) {
      if (seen.rows == r.rows && seen.columns == r.columns) {
        throw UserError("tradeoff: --resolutions lists '" + std::string(item) + "' twice");
      }
    }
    ladder.push_back(r);
    if (comma == text.size()) break;
  }
  return ladder;
}

}  // namespace fitfeel::tradeoff
