#pragma once

#include <cmath>
#include <numbers>

#include "framework/model/variation_generator.h"

namespace fitfeel::cylindrical {

// Draws from the scene's generator that give the same numbers on every platform (the standard
// library's distributions are implementation-defined).

// Uniform in [0, 1).
inline double Uniform(Rng& rng) { return UniformDraw(rng); }
inline double Uniform(Rng& rng, double a, double b) { return a + (b - a) * Uniform(rng); }

// Standard normal (Box-Muller, one value per pair of draws).
inline double Normal(Rng& rng) {
  double u1 = 0.0;
  do u1 = Uniform(rng);
  while (u1 <= 0.0);
  const double u2 = Uniform(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// Rayleigh with scale s (the length of a vector of two independent N(0, s^2) components), by
// inversion of its distribution function 1 - exp(-x^2 / 2 s^2).
inline double Rayleigh(Rng& rng, double scale) {
  double u = 0.0;
  do u = Uniform(rng);
  while (u <= 0.0);
  return scale * std::sqrt(-2.0 * std::log(u));
}

}  // namespace fitfeel::cylindrical
