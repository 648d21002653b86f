#pragma once

#include <cstdio>
#include <string>

namespace fitfeel::spherical {

// A number for a message. snprintf rather than std::to_string, whose integer path instantiates a
// GNU-unique (exported) table in the plugin; the plugin exports nothing but its hook.
inline std::string NumberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace fitfeel::spherical
