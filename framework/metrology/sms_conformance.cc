#include "framework/metrology/sms_conformance.h"

#include <algorithm>
#include <stdexcept>

#include "framework/metrology/circle_fit.h"

namespace fitfeel::metrology {

bool ConformanceReport::AllPass() const {
  return std::all_of(items.begin(), items.end(), [](const auto& i) { return i.pass; });
}

const CharacteristicResult* ConformanceReport::Find(const std::string& name) const {
  for (const auto& i : items)
    if (i.name == name) return &i;
  return nullptr;
}

CylinderSamples SamplesFromGrid(double nominal_radius, const SurfaceGrid& grid,
                                const Eigen::VectorXd& deviation) {
  if (deviation.size() != grid.size() || grid.row_position.size() != grid.rows ||
      grid.column_angle.size() != grid.columns) {
    throw std::invalid_argument("skin model shape: grid and variation sizes disagree");
  }
  CylinderSamples s;
  s.nominal_radius = nominal_radius;
  s.y = grid.row_position;
  s.theta = grid.column_angle;
  s.deviation.resize(grid.rows, grid.columns);
  for (int i = 0; i < grid.rows; ++i)
    for (int j = 0; j < grid.columns; ++j) s.deviation(i, j) = deviation(grid.index(i, j));
  return s;
}

double EvaluateCylinderForm(FormCharacteristic characteristic, const CylinderSamples& s) {
  switch (characteristic) {
    case FormCharacteristic::kRoundness: {
      if (s.theta.size() < 4) return 0.0;
      double worst = 0.0;
      const Eigen::Matrix2Xd directions = s.Directions();
      for (long i = 0; i < s.y.size(); ++i) {
        worst = std::max(
            worst, MinimumZoneRoundness(s.SectionPoints(static_cast<int>(i), directions)).value);
      }
      return worst;
    }
    case FormCharacteristic::kGeneratrixStraightness: {
      double worst = 0.0;
      Eigen::Matrix2Xd profile(2, s.y.size());
      profile.row(0) = s.y.transpose();
      for (long j = 0; j < s.theta.size(); ++j) {
        profile.row(1) = s.deviation.col(j).transpose();
        worst = std::max(worst, ProfileStraightness(profile));
      }
      return worst;
    }
    case FormCharacteristic::kAxisStraightness:
      if (s.theta.size() < 3) return 0.0;
      return AxisStraightness(s.y, SectionCentres(s));
    case FormCharacteristic::kCylindricity:
      return MinimumZoneCylindricity(s).value;
    default:
      throw std::invalid_argument("a cylinder has no characteristic '" + ToString(characteristic) +
                                  "'");
  }
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

}  // namespace fitfeel::metrology
