#include "surfaces/thread/turn_load_distribution.h"

#include <algorithm>
#include <cmath>

#include "surfaces/thread/bolting_arguments.h"

namespace fitfeel::thread {
namespace {

// sinh(a) / sinh(b) for 0 <= a <= b without overflow at large b (lambda L beyond 710).
double SinhRatio(double a, double b) {
  if (b < 20.0) return std::sinh(a) / std::sinh(b);
  return std::exp(a - b) * (1.0 - std::exp(-2.0 * a)) / (1.0 - std::exp(-2.0 * b));
}

}  // namespace

double SopwithDecayRate(double flank_stiffness_per_length, double bolt_axial_stiffness,
                        double nut_axial_stiffness) {
  constexpr const char* kFunction = "SopwithDecayRate";
  RequirePositive(kFunction, "flank_stiffness_per_length", flank_stiffness_per_length,
                  Dimension::kPressure);
  RequirePositive(kFunction, "bolt_axial_stiffness", bolt_axial_stiffness, Dimension::kForce);
  RequirePositive(kFunction, "nut_axial_stiffness", nut_axial_stiffness, Dimension::kForce);
  return std::sqrt(flank_stiffness_per_length *
                   (1.0 / bolt_axial_stiffness + 1.0 / nut_axial_stiffness));
}

std::vector<double> TurnLoadShares(double engaged_length, double pitch, double decay_rate) {
  constexpr const char* kFunction = "TurnLoadShares";
  RequirePositive(kFunction, "pitch", pitch, Dimension::kLength);
  RequirePositive(kFunction, "engaged_length", engaged_length, Dimension::kLength);
  // Beyond 10^4 turns no nut exists; the bound keeps the vector's size sane.
  RequireWithin(kFunction, "engaged_length", engaged_length, 0.0, 1e4 * pitch, Dimension::kLength);
  RequireNonNegative(kFunction, "decay_rate", decay_rate, Dimension::kDimensionless);
  // A remainder below a millionth of a pitch is rounding of a whole number of turns.
  const int turns = std::max(1, static_cast<int>(std::ceil(engaged_length / pitch - 1e-6)));
  std::vector<double> shares(turns);
  const double total = decay_rate * engaged_length;
  for (int i = 0; i < turns; ++i) {
    const double near = std::max(0.0, engaged_length - i * pitch);
    const double far = i + 1 == turns ? 0.0 : std::max(0.0, engaged_length - (i + 1) * pitch);
    shares[i] = total > 0.0
                    ? SinhRatio(decay_rate * near, total) - SinhRatio(decay_rate * far, total)
                    : (near - far) / engaged_length;
  }
  return shares;
}

}  // namespace fitfeel::thread
