#include "surfaces/cylindrical/process_model.h"

#include <cmath>
#include <numbers>
#include <string>

#include "framework/core/error.h"
#include "surfaces/cylindrical/random_draws.h"

namespace fitfeel::cylindrical {
namespace {

// A capable process scraps a tiny fraction; a limit this high means the process cannot make the
// part at all (e.g. a form spread wider than the size tolerance leaves the size no room).
constexpr int kMaxRedraws = 100000;

}  // namespace

NormalLaw SizeLaw(const ProcessSpec& process, double lower, double upper, Role role) {
  if (!(lower < upper)) throw UserError("a statistical process needs a size tolerance > 0");
  if (!(process.cp > 0.0) || !(process.cpk > 0.0) || process.cpk > process.cp) {
    throw UserError("process capability needs 0 < Cpk <= Cp, got Cp " +
                    std::to_string(process.cp) + ", Cpk " + std::to_string(process.cpk));
  }
  NormalLaw law;
  law.sd = (upper - lower) / (6.0 * process.cp);
  const bool toward_upper =
      (role == Role::kInner) == (process.lean == ProcessLean::kMaximumMaterial);
  const double inset = 3.0 * law.sd * process.cpk;
  law.mean = toward_upper ? upper - inset : lower + inset;
  return law;
}

double FormRayleighScale(double tolerance, double cpk) {
  if (!(cpk > 0.0)) throw UserError("form capability Cpk must be > 0");
  return tolerance / (std::sqrt(std::numbers::pi / 2.0) +
                      3.0 * cpk * std::sqrt((4.0 - std::numbers::pi) / 2.0));
}

double DrawFormUtilisation(const ProcessSpec& process, Rng& rng, int* rejections) {
  const double scale = FormRayleighScale(1.0, process.form_cpk);
  for (int k = 0; k < kMaxRedraws; ++k) {
    const double r = Rayleigh(rng, scale);
    if (r < 1.0) return r;
    ++*rejections;
  }
  throw UserError("the form process rejects every part (form Cpk " +
                  std::to_string(process.form_cpk) + " is far too low)");
}

}  // namespace fitfeel::cylindrical
