#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel::plot::testing {

// A part with ISO-like deviations (m) and no geometry: the maps need only name, role and size.
inline PartSpec SyntheticPart(const std::string& name, Role role, double lower, double upper,
                              const std::string& code) {
  PartSpec part;
  part.name = name;
  part.role = role;
  part.size = {20e-3, lower, upper, code};
  return part;
}

// The paper's case-1 pair, Ø20 H7/js6. ISO 286 for 20 mm: js6 = +/-6.5 um, H7 = 0 / +21 um.
inline const PartSpec kShaft = SyntheticPart("shaft", Role::kInner, -6.5e-6, 6.5e-6, "js6");
inline const PartSpec kBushing = SyntheticPart("bushing", Role::kOuter, 0.0, 21e-6, "H7");

// A cylinder grid of `rows` x `columns` equal cells over `length` (m) and a variation that stays
// inside the part's radial limits: a size offset plus a lobed, axially waving form.
inline SkinModelShape SyntheticSms(const PartSpec& part, int rows, int columns, double length,
                                   double phase) {
  SkinModelShape sms;
  SurfaceGrid& g = sms.grid;
  g.rows = rows;
  g.columns = columns;
  g.row_position.resize(rows);
  g.column_angle.resize(columns);
  for (int i = 0; i < rows; ++i) g.row_position(i) = (i + 0.5) * length / rows;
  for (int j = 0; j < columns; ++j)
    g.column_angle(j) = (j + 0.5) * 2.0 * std::numbers::pi / columns;
  g.centre.setZero(3, g.size());
  g.normal.setZero(3, g.size());
  g.area.setConstant(g.size(), 2.0 * std::numbers::pi * 10e-3 * length / g.size());
  const double low = 0.5 * part.size.lower_deviation, high = 0.5 * part.size.upper_deviation;
  const double mid = 0.5 * (low + high), half = 0.5 * (high - low);
  sms.variation.resize(g.size());
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const double form = std::cos(3.0 * g.column_angle(j) + phase) *
                          std::sin(2.0 * std::numbers::pi * g.row_position(i) / 0.025 + phase);
      sms.variation(g.index(i, j)) = mid + 0.3 * half + 0.6 * half * form;
    }
  }
  sms.dimension_part.setConstant(g.size(), mid + 0.3 * half);
  sms.form_part = sms.variation - sms.dimension_part;
  sms.surface_part.setZero(g.size());
  return sms;
}

}  // namespace fitfeel::plot::testing
