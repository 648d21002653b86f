#pragma once

#include <string>

namespace fitfeel {

// A lone CR (classic Mac OS, some spreadsheet exports) ends a line as LF and CR LF do; the readers
// split on LF only, so each lone CR becomes an LF here. Line numbers stay those an editor shows.
inline std::string NormalizeLineEndings(std::string text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
  }
  return text;
}

}  // namespace fitfeel
