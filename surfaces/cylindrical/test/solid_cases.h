#pragma once

// The 3-D CalculiX cases (tools/fem/data/solid.csv, tools/fem/solid.py) as the cylinder's elastic
// model sees them, for the tests that check the model against them and the benchmark that charts
// its error against its cost. Uses FITFEEL_TEST_SOURCE_DIR.

#include <cmath>
#include <string>
#include <vector>

#include "framework/core/config_node.h"
#include "framework/testing/fem_data.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/cylindrical_options.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

namespace fitfeel::cylindrical::testing {

// The shaft (20 mm, flush in the 20 mm hub of d2 = 30 mm, steel, no texture) drawn at
// delta0 + h (2 z / L)^2 cos(n theta) over a true bore: for n = 1 a shaft bent in a parabola of
// sagitta h, for n >= 2 lobes growing from the middle towards the ends.
struct SolidCase {
  std::string name;
  int order = 0;
  double delta0 = 0.0, amplitude = 0.0;  // m
  double fem_force = 0.0;                // the FEM's normal force, N

  explicit SolidCase(const std::string& case_name) : name(case_name) {
    using test_support::FemValue;
    order = static_cast<int>(FemValue("solid.csv", name, 1));
    delta0 = FemValue("solid.csv", name, 2) * kUm;
    amplitude = FemValue("solid.csv", name, 3) * kUm;
    fem_force = FemValue("solid.csv", name, 4);
  }
  // The shaft's radial deviation at row i of 40 and column j of 72.
  double ShaftDeviation(int i, int j) const {
    const double z = (i + 0.5) * 0.020 / 40 - 0.010;
    return delta0 + amplitude * std::pow(2.0 * z / 0.020, 2) * std::cos(order * 2 * kPi * j / 72);
  }
};

inline const std::vector<std::string>& SolidCaseNames() {
  static const std::vector<std::string> names{"uniform-flush",     "bent-full",
                                              "bent-clearance",    "bent-partial",
                                              "oval-ends-partial", "lobed3-ends-partial"};
  return names;
}

// The elastic model's normal force on the case fully engaged (at the tabulated anchor), with the
// law's `options` (model.options).
inline double SolidCaseElasticForce(const SolidCase& c, const std::string& options) {
  const PartSpec shaft = MakeShaft(0.020, 0.020), bushing = MakeBushing(0.020, 0.020, 0.030);
  ModelSettings settings = Settings(0.15, 0.0, TextureMode::kSampled);
  settings.law = "elastic";
  settings.options = ParsedOptions(options);
  CylinderContactAnalyzer analyzer;
  analyzer.Prepare(
      shaft,
      MakeSms(MakeGrid(40, 72, 0.020, 0.020), [&](int i, int j) { return c.ShaftDeviation(i, j); }),
      bushing, MakeSms(MakeGrid(40, 72, 0.020, 0.020), [](int, int) { return 0.0; }), settings);
  MatingPose pose;
  pose.depth = 0.020;
  pose.offset = analyzer.anchor(static_cast<int>(std::lround(0.020 / analyzer.depth_step())));
  ContactState state;
  analyzer.Evaluate(pose, &state);
  return state.normal_force;
}

}  // namespace fitfeel::cylindrical::testing
