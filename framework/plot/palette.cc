#include "framework/plot/palette.h"

#include <cmath>

namespace fitfeel::plot {

double RelativeLuminance(unsigned rgb) {
  const auto linear = [](unsigned channel) {
    const double c = static_cast<double>(channel & 0xffu) / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(rgb >> 16) + 0.7152 * linear(rgb >> 8) + 0.0722 * linear(rgb);
}

}  // namespace fitfeel::plot
