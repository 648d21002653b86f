#pragma once

#include <string>
#include <vector>

#include "framework/metrology/cylinder_form.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel::cylindrical {

// Rounding allowance of the evaluations, 1 pm: 10^-5 of the tightest tolerance a scene can carry
// in practice (0.1 um), far below anything a measurement could resolve.
inline constexpr double kEvaluationSlack = 1e-12;

// One evaluated characteristic beside its specification.
struct CharacteristicResult {
  std::string name;         // "size", "roundness", "axis_straightness", ...
  std::string method;       // how it was evaluated, for reports
  bool specified = false;   // the part's spec gives a limit for it
  double value = 0.0;       // form: zone width; size: largest two-point deviation (m)
  double value_low = 0.0;   // size: smallest two-point deviation; form: 0 (m)
  double limit_low = 0.0;   // size: lower deviation; form: 0 (m)
  double limit_high = 0.0;  // size: upper deviation; form: tolerance (m)
  bool pass = true;         // not specified: always true
};

struct ConformanceReport {
  std::vector<CharacteristicResult> items;
  bool AllPass() const;
  const CharacteristicResult* Find(const std::string& name) const;  // null if absent
};

// Evaluates a cylindrical skin model shape against every tolerance of its part: two-point sizes
// (ISO 14405-1 default) on the whole V; form characteristics on V minus the sampled texture, as
// ISO 12180/12181/12780 do after their profile filters remove wavelengths shorter than the form
// (texture here is, by the paper, below 10 mm). Unspecified form characteristics are evaluated
// for information and marked not specified.
ConformanceReport EvaluateCylindricalSms(const PartSpec& part, const SkinModelShape& sms);

}  // namespace fitfeel::cylindrical
