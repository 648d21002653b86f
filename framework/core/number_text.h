#pragma once
// Numbers as text, in the two forms fitfeel writes: the shortest decimal that reads back as the
// same double (outputs, charts, studies: a value survives a round trip through its file), and six
// significant digits for messages a person reads.
#include <charconv>
#include <cstdio>
#include <string>

namespace fitfeel {

inline void AppendShortestDecimal(std::string* out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out->append(buffer, result.ptr);
}

inline std::string ShortestDecimal(double value) {
  std::string text;
  AppendShortestDecimal(&text, value);
  return text;
}

// snprintf rather than std::to_string, whose "%f" hides micrometres (and whose integer path puts
// a GNU-unique table into a plugin that uses it).
inline std::string MessageNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace fitfeel
