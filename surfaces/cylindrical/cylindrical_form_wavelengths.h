#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fitfeel::cylindrical {

// Wavelength bands of ISO GPS as the paper uses them (section 2.2): form deviations have
// wavelengths of at least 10 mm; waviness 1-10 mm and roughness below 1 mm are texture, which the
// model treats statistically and which therefore needs no cells.
inline constexpr double kMinFormWavelength = 10e-3;  // m

// Grid points per shortest represented wave, axially and around. With 8 samples per wave the
// piecewise-linear reading of a sampled sinusoid stays within 1 - cos(pi/8) = 7.6 % of its
// amplitude, and the peaks and troughs the paper samples (every half wave) fall at most 1/16 of a
// wave from a row.
inline constexpr int kSamplesPerWave = 8;

// Highest roundness harmonic the generator makes: undulations per revolution (UPR) whose
// circumferential wavelength pi*d/k is still a form wavelength (>= 10 mm), at least 2 (ovality,
// the commonest roundness error, also on small parts) and at most 50 UPR, the default
// long-wave-pass cut-off of ISO 12181-2 for roundness.
inline int MaxRoundnessHarmonic(double diameter) {
  const int by_wavelength =
      static_cast<int>(std::floor(std::numbers::pi * diameter / kMinFormWavelength));
  return std::clamp(by_wavelength, 2, 50);
}

// Fewest columns of an automatic grid. The assembly space is a polygon with one side per column
// direction; with 48 directions its extent overestimates a circle's by 1/cos(pi/48) - 1 = 0.21 %.
inline constexpr int kMinAutoColumns = 48;
// Fewest rows: three sections are the least on which an axis can be bent.
inline constexpr int kMinAutoRows = 3;

}  // namespace fitfeel::cylindrical
