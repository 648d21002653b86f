#include "surfaces/cylindrical/sms_conformance.h"

#include <algorithm>

#include "framework/metrology/cylinder_form.h"

namespace fitfeel::cylindrical {

using metrology::CylinderSamples;
using metrology::EvaluateCylinderForm;
using metrology::SamplesFromGrid;
using metrology::SizeRange;
using metrology::TwoPointSizes;

bool ConformanceReport::AllPass() const {
  return std::all_of(items.begin(), items.end(), [](const auto& i) { return i.pass; });
}

const CharacteristicResult* ConformanceReport::Find(const std::string& name) const {
  for (const auto& i : items)
    if (i.name == name) return &i;
  return nullptr;
}

ConformanceReport EvaluateCylindricalSms(const PartSpec& part, const SkinModelShape& sms) {
  const double radius = part.size.nominal / 2.0;
  ConformanceReport report;
  const CylinderSamples whole = SamplesFromGrid(radius, sms.grid, sms.variation);
  {
    CharacteristicResult size;
    size.name = "size";
    size.method = "two-point (ISO 14405-1 LP), every opposite cell pair";
    size.specified = true;
    const SizeRange r = TwoPointSizes(whole);
    size.value_low = r.min;
    size.value = r.max;
    size.limit_low = part.size.lower_deviation;
    size.limit_high = part.size.upper_deviation;
    size.pass =
        r.min >= size.limit_low - kEvaluationSlack && r.max <= size.limit_high + kEvaluationSlack;
    report.items.push_back(size);
  }
  Eigen::VectorXd form = sms.variation;
  if (sms.surface_part.size() == form.size()) form -= sms.surface_part;
  const CylinderSamples filtered = SamplesFromGrid(radius, sms.grid, form);
  struct Item {
    FormCharacteristic c;
    const char* method;
  };
  const Item items[] = {
      {FormCharacteristic::kAxisStraightness,
       "least-squares section centres, minimum cylinder (ISO 12780)"},
      {FormCharacteristic::kGeneratrixStraightness,
       "minimum zone, worst generatrix (convex hull width)"},
      {FormCharacteristic::kRoundness, "minimum zone, worst section (MZCI, ISO 12181)"},
      {FormCharacteristic::kCylindricity, "minimum zone, linearised (MZCY, ISO 12180)"},
  };
  for (const auto& item : items) {
    CharacteristicResult r;
    r.name = ToString(item.c);
    r.method = item.method;
    r.value = EvaluateCylinderForm(item.c, filtered);
    const auto it = part.form.tolerance.find(item.c);
    r.specified = it != part.form.tolerance.end();
    if (r.specified) {
      r.limit_high = it->second;
      r.pass = r.value <= r.limit_high + kEvaluationSlack;
    }
    report.items.push_back(r);
  }
  return report;
}

}  // namespace fitfeel::cylindrical
