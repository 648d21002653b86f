#pragma once

#include <array>

#include "framework/core/export.h"

namespace fitfeel::plot {

// Anchors of the viridis colour map (van der Walt and Smith, matplotlib 2.0), sampled at ten
// equally spaced points and interpolated by gnuplot. Viridis is perceptually uniform and its
// lightness rises monotonically, so a map stays readable printed in grey or seen by readers with
// a colour-vision deficiency.
inline constexpr std::array<unsigned, 10> kViridis = {0x440154, 0x482878, 0x3e4a89, 0x31688e,
                                                      0x26828e, 0x1f9e89, 0x35b779, 0x6dcd59,
                                                      0xb4de2c, 0xfde725};

// Line colours for curves of different runs: the Okabe-Ito colour-blind-safe set, paired with
// distinct dash patterns so that the curves stay apart in grey.
inline constexpr std::array<unsigned, 7> kLineColours = {0x0072b2, 0xd55e00, 0x009e73, 0xcc79a7,
                                                         0x000000, 0xe69f00, 0x56b4e9};

// Relative luminance (ITU-R BT.709 weights on linearised sRGB) of a 0xRRGGBB colour, 0..1.
FITFEEL_API double RelativeLuminance(unsigned rgb);

}  // namespace fitfeel::plot
