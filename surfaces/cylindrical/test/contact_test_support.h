#pragma once

// Synthetic skin model shapes for the contact tests and benchmarks: an m x n grid on a nominal
// cylinder and a variation given per cell, with no dependence on the discretizer or generator.

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"
#include "framework/model/skin_model_shape.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"
#include "surfaces/cylindrical/cylindrical_options.h"

namespace fitfeel::cylindrical::testing {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kUm = 1e-6;

// `model.options` as a scene file gives them, parsed as the loader parses them.
inline std::shared_ptr<const CylindricalOptions> ParsedOptions(const std::string& yaml,
                                                               const std::string& file = "test") {
  return ParseCylindricalOptions(ConfigNode::Parse(yaml, file, "model.options"));
}

inline SurfaceGrid MakeGrid(int rows, int columns, double diameter, double length) {
  SurfaceGrid g;
  g.rows = rows;
  g.columns = columns;
  g.row_position.resize(rows);
  g.column_angle.resize(columns);
  for (int i = 0; i < rows; ++i) g.row_position[i] = (i + 0.5) * length / rows;
  for (int j = 0; j < columns; ++j) g.column_angle[j] = 2.0 * std::numbers::pi * j / columns;
  g.centre.resize(3, g.size());
  g.normal.resize(3, g.size());
  g.area.resize(g.size());
  const double cell = std::numbers::pi * diameter * length / (rows * columns);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const int c = g.index(i, j);
      const double b = g.column_angle[j];
      g.normal.col(c) << std::cos(b), 0.0, std::sin(b);
      g.centre.col(c) << 0.5 * diameter * std::cos(b), g.row_position[i],
          0.5 * diameter * std::sin(b);
      g.area[c] = cell;
    }
  }
  return g;
}

// V(row, column) -> metres.
inline SkinModelShape MakeSms(const SurfaceGrid& grid,
                              const std::function<double(int, int)>& variation) {
  SkinModelShape s;
  s.grid = grid;
  s.variation.resize(grid.size());
  for (int i = 0; i < grid.rows; ++i) {
    for (int j = 0; j < grid.columns; ++j) s.variation[grid.index(i, j)] = variation(i, j);
  }
  s.dimension_part = s.variation;
  s.form_part = Eigen::VectorXd::Zero(grid.size());
  s.surface_part = Eigen::VectorXd::Zero(grid.size());
  return s;
}

inline Material Steel() { return Material{"steel", 210e9, 0.3}; }

inline PartSpec MakeShaft(double diameter, double length, double bore = 0.0) {
  PartSpec p;
  p.name = "shaft";
  p.role = Role::kInner;
  p.size.nominal = diameter;
  p.material = Steel();
  p.geometry = std::make_shared<CylindricalGeometry>(Role::kInner, diameter, length, 0.0, bore);
  return p;
}

inline PartSpec MakeBushing(double diameter, double length, double outer_diameter) {
  PartSpec p;
  p.name = "bushing";
  p.role = Role::kOuter;
  p.size.nominal = diameter;
  p.material = Steel();
  p.geometry =
      std::make_shared<CylindricalGeometry>(Role::kOuter, diameter, length, outer_diameter, 0.0);
  return p;
}

inline ModelSettings Settings(double mu = 0.15, double kp = 0.0,
                              TextureMode texture = TextureMode::kExpected) {
  ModelSettings s;
  s.law = "gps";
  s.friction = mu;
  s.contact_stiffness = kp;
  s.texture = texture;
  return s;
}

}  // namespace fitfeel::cylindrical::testing
