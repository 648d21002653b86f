#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/error.h"
#include "framework/testing/fem_data.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/cylindrical_options.h"
#include "surfaces/cylindrical/elastic/harmonic_compliance.h"
#include "surfaces/cylindrical/elastic_options.h"
#include "surfaces/cylindrical/test/contact_test_support.h"
#include "surfaces/cylindrical/test/solid_cases.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

ModelSettings Elastic(TextureMode texture = TextureMode::kDin7190) {
  ModelSettings s = Settings(0.15, 0.0, texture);
  s.law = "elastic";
  return s;
}

struct Outcome {
  ContactState state;
  Wrench wrench;
};

// The tabulated anchor nearest a depth.
Eigen::Vector2d AnchorNear(const CylinderContactAnalyzer& a, double depth) {
  return a.anchor(static_cast<int>(std::lround(depth / a.depth_step())));
}

Outcome OutcomeAt(const ContactAnalyzer& a, const ResistanceLaw& law, double depth,
                  Eigen::Vector2d offset) {
  MatingPose pose;
  pose.depth = depth;
  pose.offset = offset;
  Outcome r;
  a.Evaluate(pose, &r.state);
  MatingMotion motion;
  motion.velocity.y() = 0.010;
  law.Evaluate(r.state, motion, &r.wrench);
  return r;
}

// Paper case 1's pair without form: shaft 20 x 40 mm, bushing 20 x 20 mm in a 30 mm hub, steel,
// Rz 1.6 um on both, a uniform radial interference `delta` on the shaft.
struct ElasticPair {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  CylinderContactAnalyzer analyzer;
  ElasticLaw law;
  ElasticPair(const std::function<double(int, int)>& shaft_v,
              const std::function<double(int, int)>& bore_v, ModelSettings settings = Elastic(),
              int columns = 72) {
    shaft.texture = bushing.texture = TextureSpec{0.0, 0.4e-6, 1.6e-6};
    analyzer.Prepare(shaft, MakeSms(MakeGrid(40, columns, 0.020, 0.040), shaft_v), bushing,
                     MakeSms(MakeGrid(20, columns, 0.020, 0.020), bore_v), settings);
    law.Prepare(shaft, bushing, settings);
  }
};

// The axial coupling solves each part's elements once per row: a grid past its limit is refused
// saying what to change, and plane sections take it.
TEST(ElasticLaw, AxialCouplingRefusesAGridItCannotSolveInTime) {
  const int rows = AxialCoupling::kMostRows + 1;
  const PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  auto prepare = [&](const char* options) {
    ModelSettings settings = Elastic(TextureMode::kSampled);
    settings.options = ParsedOptions(options, "scene.yaml");
    CylinderContactAnalyzer analyzer;
    analyzer.Prepare(shaft, MakeSms(MakeGrid(rows, 24, 0.020, 0.040), [](int, int) { return 0.0; }),
                     bushing, MakeSms(MakeGrid(20, 24, 0.020, 0.020), [](int, int) { return 0.0; }),
                     settings);
  };
  try {
    prepare("{}");
    ADD_FAILURE() << "accepted";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the shaft has 1001"), std::string::npos) << what;
    EXPECT_NE(what.find("model.options.axial_coupling: false"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(prepare("{axial_coupling: false}"));
}

TEST(ElasticLaw, Din7190SmoothingOfAUniformPressFit) {
  // 5 um radial over the full 20 mm engagement, mu = 0.15: 1099.6 N per um of what is left after
  // smoothing 0.8 (1.6 + 1.6) um on the diameter, i.e. 1099.6 x (5 - 1.28) = 4090 N. That is
  // DIN 7190's plane sections, which the model gives without its axial coupling.
  ModelSettings plane = Elastic();
  plane.options = ParsedOptions("{axial_coupling: false}");
  ElasticPair p([](int, int) { return 5 * kUm; }, [](int, int) { return 0.0; }, plane);
  ElasticPair coupled([](int, int) { return 5 * kUm; }, [](int, int) { return 0.0; });
  EXPECT_NEAR(p.analyzer.smoothing(), 1.28 * kUm, 1e-15);
  for (double depth : {20.5e-3, 30e-3, 39.5e-3}) {
    const Outcome r = OutcomeAt(p.analyzer, p.law, depth, {0, 0});
    EXPECT_NEAR(-r.wrench.force.y(), 4090.0, 0.01 * 4090.0) << depth;
    EXPECT_NEAR(r.state.normal_force, 4090.0 / 0.15, 0.01 * 4090.0 / 0.15);
    // The shaft running on beyond the hub stiffens the engaged length (CalculiX: 1.6 % with 10 mm
    // either side, the through case of tools/fem/data/axisymmetric.csv, whose 5 um scale to the
    // 3.72 left here; the solids are linear and in contact all round).
    const Outcome c = OutcomeAt(coupled.analyzer, coupled.law, depth, {0, 0});
    EXPECT_GT(c.state.normal_force, r.state.normal_force) << depth;
    EXPECT_LT(c.state.normal_force, 1.02 * r.state.normal_force) << depth;
    if (depth == 30e-3) {
      const double fem = test_support::AxisymmetricFemForce("cylinder-through") * 3.72 / 5.0;
      EXPECT_NEAR(c.state.normal_force, fem, 0.01 * fem);
    }
  }
  // The pressure map: Lame's 5.8333 MPa per um of the smoothed 3.72 um on every engaged cell.
  MatingPose pose;
  pose.depth = 30e-3;
  Eigen::VectorXd p_map;
  ASSERT_TRUE(p.analyzer.PressureMap(pose, &p_map));
  int engaged = 0;
  for (Eigen::Index c = 0; c < p_map.size(); ++c) {
    if (p_map[c] == 0.0) continue;
    ++engaged;
    EXPECT_NEAR(p_map[c], 5.8333e6 * 3.72, 0.001 * 5.8333e6 * 3.72);
  }
  EXPECT_EQ(engaged, 20 * 72);  // the 20 shaft rows inside the bushing
  // Coupled, the same cells carry the tables' normal force, more at the hub's faces than in its
  // middle (the unloaded shaft beyond each face holds the loaded one).
  ASSERT_TRUE(coupled.analyzer.PressureMap(pose, &p_map));
  ContactState state;
  coupled.analyzer.Evaluate(pose, &state);
  const double cell_area = kPi * 0.020 * 0.040 / (40 * 72);  // the shaft's grid: equal cells
  EXPECT_NEAR(p_map.sum() * cell_area, state.normal_force, 1e-3 * state.normal_force);
  const int face_row = 10, middle_row = 20;  // the shaft's rows at the entrance and in the middle
  EXPECT_GT(p_map[face_row * 72], 1.05 * p_map[middle_row * 72]);
  EXPECT_GT(p_map[middle_row * 72], 0.0);
}

TEST(ElasticLaw, InterferenceBelowTheSmoothingLeavesOnlyTheWeight) {
  // 1.2 um radial < 1.28 um: the fit is loose after joining. A part held off its free position so
  // that the radial spring carries a 2 N weight feels mu x 2 N, nothing from the texture.
  for (double delta : {0.0, 0.6, 1.2}) {
    ElasticPair p([&](int, int) { return delta * kUm; }, [](int, int) { return 0.0; });
    const Outcome free = OutcomeAt(p.analyzer, p.law, 30e-3, {0, 0});
    EXPECT_EQ(free.state.normal_force, 0.0);
    EXPECT_EQ(free.wrench.force.y(), 0.0);
    // Settle under 2 N downward: the clearance, then the spring's travel for 2 N.
    const double k = LameRadialStiffness(p.law.pressure_per_interference(), 0.020, 0.020);
    const double clearance = (1.28 - delta) * kUm;
    const Outcome held = OutcomeAt(p.analyzer, p.law, 30e-3, {0.0, -(clearance + 2.0 / k)});
    EXPECT_NEAR(held.wrench.force.z(), 2.0, 0.01) << delta;
    EXPECT_NEAR(-held.wrench.force.y(), 0.15 * 2.0, 0.002) << delta;
  }
}

TEST(ElasticLaw, OvalInterferenceCarriesOnlyItsMean) {
  // delta0 + delta2 cos 2 theta with delta0 >= 0.145 delta2: full contact, normal force exactly
  // P0 delta0 pi d L on plane sections (no roughness here, so nothing is smoothed). With the axial
  // coupling (where the contact stays all round), exactly what the uniform delta0 gives: the
  // ovality adds nothing to the breathing.
  const double p0 = 5.8333e12;
  ModelSettings plane = Elastic(TextureMode::kSampled);
  plane.options = ParsedOptions("{axial_coupling: false}");
  for (double ratio : {0.15, 0.3, 1.0}) {
    const double d2 = 4 * kUm, d0 = ratio * d2;
    auto oval = [&](int, int j) { return d0 + d2 * std::cos(2 * 2 * kPi * j / 360); };
    ElasticPair q(
        oval, [](int, int) { return 0.0; }, plane, 360);
    const Outcome r = OutcomeAt(q.analyzer, q.law, 30e-3, {0, 0});
    EXPECT_NEAR(r.state.normal_force / (p0 * d0 * kPi * 0.020 * 0.020), 1.0, 1e-4) << ratio;
    // In 3-D the ovality of a 20 mm part is 7 % stiffer than its plane-stress sections in the
    // middle (axial_coupling_test.cc), so 0.15 is no longer all round there.
    if (ratio < 0.2) continue;
    ElasticPair coupled(
        oval, [](int, int) { return 0.0; }, Elastic(TextureMode::kSampled), 360);
    ElasticPair uniform([&](int, int) { return d0; }, [](int, int) { return 0.0; },
                        Elastic(TextureMode::kSampled), 360);
    const double n_uniform =
        OutcomeAt(uniform.analyzer, uniform.law, 30e-3, {0, 0}).state.normal_force;
    EXPECT_NEAR(OutcomeAt(coupled.analyzer, coupled.law, 30e-3, {0, 0}).state.normal_force,
                n_uniform, 1e-4 * n_uniform)
        << ratio;
  }
}

TEST(ElasticLaw, TiltedBoreWithinTheClearanceCarriesNothing) {
  // The bore's axis tilted by phi in the x-y plane, 3 um radial clearance, 20 mm engagement.
  for (double half_misalignment : {2.0, 4.0}) {  // phi L / 2, um
    const double phi = half_misalignment * kUm / 0.010;
    auto bore = [&](int i, int j) {
      const double y = (i + 0.5) * 0.020 / 20 - 0.010;
      return phi * y * std::cos(2 * kPi * j / 72);
    };
    auto shaft = [](int, int) { return -3 * kUm; };
    ModelSettings free = Elastic(TextureMode::kSampled);
    ElasticPair p(shaft, bore, free);
    const Outcome r = OutcomeAt(p.analyzer, p.law, 30e-3, AnchorNear(p.analyzer, 30e-3));
    EXPECT_LT(r.state.normal_force, 1e-6) << half_misalignment;
    EXPECT_EQ(r.wrench.force.y(), 0.0) << half_misalignment;
    if (half_misalignment > 3.0) {
      // The bore tilts further than the clearance allows a straight part: it must tilt with it.
      EXPECT_NEAR(
          p.analyzer.tilt(static_cast<int>(std::lround(30e-3 / p.analyzer.depth_step()))).x(), phi,
          0.3 * phi);
      // Held straight, the same part is pressed at both ends of the bore.
      ModelSettings fixed = free;
      fixed.options = ParsedOptions("{tilt: fixed}");
      ElasticPair held(shaft, bore, fixed);
      EXPECT_GT(OutcomeAt(held.analyzer, held.law, 30e-3, AnchorNear(held.analyzer, 30e-3))
                    .state.normal_force,
                10.0);
    }
  }
}

// The tilted bore with interference, reduced without a 3-D FEM: a rigid rotation of one part
// changes nothing in linear elasticity, so a part free to tilt seats along the bore's axis and
// meets exactly the aligned fit's contact (docs/contact-mechanics.md, section 7).
TEST(ElasticLaw, TiltedBoreWithInterferenceIsTheAlignedFitForAPartFreeToTilt) {
  auto shaft = [](int, int) { return 5 * kUm; };
  ElasticPair aligned(
      shaft, [](int, int) { return 0.0; }, Elastic(TextureMode::kSampled));
  const double expected =
      OutcomeAt(aligned.analyzer, aligned.law, 30e-3, AnchorNear(aligned.analyzer, 30e-3))
          .state.normal_force;
  for (double half_misalignment : {2.0, 8.0}) {  // phi L / 2, um: within and beyond 5 um
    const double phi = half_misalignment * kUm / 0.010;
    auto bore = [&](int i, int j) {
      const double y = (i + 0.5) * 0.020 / 20 - 0.010;
      return phi * y * std::cos(2 * kPi * j / 72);
    };
    ElasticPair tilted(shaft, bore, Elastic(TextureMode::kSampled));
    const Outcome r =
        OutcomeAt(tilted.analyzer, tilted.law, 30e-3, AnchorNear(tilted.analyzer, 30e-3));
    EXPECT_NEAR(r.state.normal_force, expected, 1e-6 * expected) << half_misalignment;
    const int step = static_cast<int>(std::lround(30e-3 / tilted.analyzer.depth_step()));
    EXPECT_NEAR(tilted.analyzer.tilt(step).x(), phi, 1e-6 * phi) << half_misalignment;
  }
}

TEST(ElasticLaw, ColumnsOptionSetsTheSolveResolution) {
  // 240 grid columns: averaged in pairs to 120 by default, solved on all of them with
  // columns: 240; an odd count or one outside 24..1440 is refused where it is written.
  auto columns_of = [](const char* options) {
    ModelSettings s = Elastic(TextureMode::kSampled);
    if (options != nullptr) s.options = ParsedOptions(options, "scene.yaml");
    ElasticPair p([](int, int) { return 2 * kUm; }, [](int, int) { return 0.0; }, s, 240);
    return p.analyzer.elastic_columns();
  };
  EXPECT_EQ(columns_of(nullptr), 120);
  EXPECT_EQ(columns_of("{columns: 240}"), 240);
  EXPECT_EQ(columns_of("{columns: 60}"), 60);
  for (const char* bad : {"{columns: 121}", "{columns: 12}", "{columns: 2000}", "{columns: x}"}) {
    try {
      ParsedOptions(bad, "scene.yaml");
      ADD_FAILURE() << bad << " accepted";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find("model.options.columns"), std::string::npos) << e.what();
    }
  }
}

// Blocks of grid columns reach the elastic solve as the grid's Fourier series up to the solve's
// highest harmonic: a bore's waviness of order 20 or 50 on 360 columns, pressed at its crests
// (the shaft 0.5 um over the bore's mean radius, the waviness 2 um high), carries on 120 solve
// columns the force it carries on all 360 within 8 % (order 50: -7.0 %, its crests sampled 2.4
// times a wave). Blocks' means flattened order 50 to 74 % of its height: -21 %.
TEST(ElasticLaw, SolveColumnsKeepTheHarmonicsTheyResolve) {
  for (int order : {20, 50}) {
    auto force = [order](const char* options) {
      ModelSettings s = Elastic(TextureMode::kSampled);
      s.options = ParsedOptions(options, "scene.yaml");
      ElasticPair p([](int, int) { return 0.5 * kUm; },
                    [order](int, int j) {
                      return 1.0 * kUm * std::cos(order * 2.0 * std::numbers::pi * j / 360.0);
                    },
                    s, 360);
      // The shaft through the whole bore.
      const int k = static_cast<int>(std::lround(0.030 / p.analyzer.depth_step()));
      EXPECT_TRUE(p.analyzer.interference_at(k));
      return p.analyzer.normal_force(k);
    };
    const double all = force("{columns: 360}"), solve = force("{}");
    EXPECT_GT(all, 0.0);
    EXPECT_NEAR(solve, all, 0.08 * all) << "order " << order;
  }
}

// A row of the accuracy chart's data, appended to the file the variable `table` names when set
// (docs/figures/regenerate.sh sets it and writes the header): case, FEM, elastic model, its
// error, the comparison (the paper law, or plane sections: the paper law's per-cell Lame for a
// uniform interference), its error.
void ChartRow(const char* table, const char* name, double fem, double model, double other) {
  const char* path = std::getenv(table);
  if (path == nullptr) return;
  std::FILE* f = std::fopen(path, "a");
  ASSERT_NE(f, nullptr) << path;
  std::fprintf(f, "%s,%.6g,%.6g,%.6g,%.6g,%.6g\n", name, fem, model, model / fem - 1.0, other,
               other / fem - 1.0);
  std::fclose(f);
}

// tools/fem/data/contact.csv: CalculiX plane-stress sections, steel d1 = 20 in d2 = 30 mm.
struct FemCase {
  std::string name, kind;
  int n = 0;
  double d0 = 0, dn = 0, width = 0, force_per_mm = 0;
};

std::vector<FemCase> LoadFemCases() {
  std::ifstream in(std::string(FITFEEL_TEST_SOURCE_DIR) + "/tools/fem/data/contact.csv");
  std::vector<FemCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("case,", 0) == 0) continue;
    std::stringstream ss(line);
    std::string f[8];
    for (auto& x : f) std::getline(ss, x, ',');
    cases.push_back({f[0], f[1], std::stoi(f[2]), std::stod(f[3]), std::stod(f[4]), std::stod(f[5]),
                     std::stod(f[6])});
  }
  return cases;
}

double Interference(const FemCase& c, double theta) {  // um, as tools/fem/fem.py builds it
  if (c.kind == "bump") {
    const double t = std::remainder(theta, 2 * kPi);
    return c.d0 + c.dn * std::exp(-0.5 * std::pow(0.010 * 1e3 * t / c.width, 2));
  }
  return c.d0 + c.dn * std::cos(c.n * theta);
}

// Every FEM case within 10 %: uniform, lobed n = 2, 3, 5, 10 in full and partial contact, and a
// Gaussian bump of 0.5, 1.5 and 4.5 mm on a clearance (the shaft floats to its equilibrium in
// both). The FEM's normal force comes from its displacements (tools/fem/fem.py says why).
TEST(ElasticLaw, AgreesWithCalculixOnEveryContactCase) {
  const std::vector<FemCase> cases = LoadFemCases();
  ASSERT_EQ(cases.size(), 12u);  // every case of tools/fem/fem.py contact_cases()
  std::printf("%-16s %12s %12s %8s %12s %8s\n", "case", "FEM N/mm", "elastic", "error", "paper law",
              "error");
  for (const FemCase& c : cases) {
    const int columns = 240;  // the FEM's elements around
    auto shaft = [&](int, int j) { return Interference(c, 2 * kPi * (j + 0.5) / columns) * kUm; };
    // The elastic solve on every grid column: the 0.5 mm bump is two of them wide. The FEM is a
    // plane section: so is the model here (the shaft runs through the hub, whose ends its
    // axial coupling would stiffen by 1.6 %, as the axisymmetric cases below check).
    ModelSettings fine = Elastic(TextureMode::kSampled);
    fine.options = ParsedOptions("{columns: 240, axial_coupling: false}");
    ElasticPair elastic(
        shaft, [](int, int) { return 0.0; }, fine, columns);
    elastic.shaft.texture = TextureSpec{};
    ModelSettings paper = Settings(0.15, 0.0, TextureMode::kSampled);
    ElasticPair gps(
        shaft, [](int, int) { return 0.0; }, paper, columns);
    GpsLaw gps_law;
    gps_law.Prepare(gps.shaft, gps.bushing, paper);
    const Outcome e =
        OutcomeAt(elastic.analyzer, elastic.law, 30e-3, AnchorNear(elastic.analyzer, 30e-3));
    const Outcome g = OutcomeAt(gps.analyzer, gps_law, 30e-3, AnchorNear(gps.analyzer, 30e-3));
    const double model = e.state.normal_force / 20.0;  // N per mm of the 20 mm engagement
    const double law = gps_law.pressure_per_interference() * g.state.interference_volume / 20.0;
    const double err = model / c.force_per_mm - 1.0, err_paper = law / c.force_per_mm - 1.0;
    std::printf("%-16s %12.2f %12.2f %+7.1f%% %12.2f %+7.1f%%\n", c.name.c_str(), c.force_per_mm,
                model, 100 * err, law, 100 * err_paper);
    EXPECT_LT(std::abs(err), 0.10) << c.name;
    ChartRow("FITFEEL_FEM_ACCURACY_CSV", c.name.c_str(), c.force_per_mm, model, law);
  }
}

// tools/fem/data/axisymmetric.csv (AxisymmetricFemForce): CalculiX in axisymmetry, the paper's
// pair (shaft 20 mm in a hub 20 mm long, outer diameter 30 mm, steel) with a uniform radial
// interference of 5 um, no texture, frictionless; the normal force B of each case.

// The paper's pair with the shaft `shaft_length` long in a hub of outer diameter `hub_diameter`,
// the shaft's rim drawn at `shaft_v` (row, column of 72) over a true bore, no texture, the
// analyzer prepared with `settings` and `options`.
struct FieldPair {
  PartSpec shaft, bushing;
  ModelSettings settings;
  CylinderContactAnalyzer analyzer;
  FieldPair(const std::function<double(int, int)>& shaft_v, double shaft_length, ModelSettings base,
            const std::string& options, double hub_diameter = 0.030, double shaft_row = 0.5e-3)
      : shaft(MakeShaft(0.020, shaft_length)),
        bushing(MakeBushing(0.020, 0.020, hub_diameter)),
        settings(std::move(base)) {
    settings.options = ParsedOptions(options);
    const int rows = static_cast<int>(std::lround(shaft_length / shaft_row));
    analyzer.Prepare(shaft, MakeSms(MakeGrid(rows, 72, 0.020, shaft_length), shaft_v), bushing,
                     MakeSms(MakeGrid(40, 72, 0.020, 0.020), [](int, int) { return 0.0; }),
                     settings);
    EXPECT_EQ(analyzer.smoothing(), 0.0);
  }
};

// The elastic model's normal force of that pair at `depth`, at the tabulated anchor.
double NormalForce(const std::function<double(int, int)>& shaft_v, double shaft_length,
                   double depth, const std::string& options, double hub_diameter = 0.030,
                   double shaft_row = 0.5e-3) {
  FieldPair p(shaft_v, shaft_length, Elastic(TextureMode::kSampled), options, hub_diameter,
              shaft_row);
  ElasticLaw law;
  law.Prepare(p.shaft, p.bushing, p.settings);
  return OutcomeAt(p.analyzer, law, depth, AnchorNear(p.analyzer, depth)).state.normal_force;
}

// The paper law's: eq. 9's pressure per unit interference times the interference volume.
double PaperLawNormalForce(const std::function<double(int, int)>& shaft_v, double shaft_length,
                           double depth) {
  FieldPair p(shaft_v, shaft_length, Settings(0.15, 0.0, TextureMode::kSampled), "{}");
  GpsLaw law;
  law.Prepare(p.shaft, p.bushing, p.settings);
  return law.pressure_per_interference() *
         OutcomeAt(p.analyzer, law, depth, AnchorNear(p.analyzer, depth)).state.interference_volume;
}

// The same with a uniform radial interference of 5 um.
double UniformNormalForce(double shaft_length, double depth, const std::string& options,
                          double hub_diameter = 0.030, double shaft_row = 0.5e-3) {
  return NormalForce([](int, int) { return 5 * kUm; }, shaft_length, depth, options, hub_diameter,
                     shaft_row);
}

// The fully engaged finite hub: plane sections are exact in plane strain (the FEM's slice held
// between planes) and within 2 % for the free hub with the shaft flush with it or running through
// it (the hub's free ends and the shaft's continuation nearly cancel). The axial coupling changes
// nothing where both parts are loaded over their whole length (a uniform load bends nothing) and
// takes the through shaft from -1.55 % to the FEM's force: its unloaded ends stiffen the loaded
// middle. Asserted: 1 % (measured: within 0.02 %).
TEST(ElasticLaw, AgreesWithCalculixOnTheFullyEngagedFiniteHub) {
  struct Case {
    const char* name;
    double shaft_length, depth;
    const char* options;        // the model's
    const char* plane_options;  // the same without the axial coupling
  };
  for (const Case& c : {Case{"cylinder-plane-strain", 0.020, 0.020, "{section: plane_strain}",
                             "{section: plane_strain, axial_coupling: false}"},
                        Case{"cylinder-flush", 0.020, 0.020, "{}", "{axial_coupling: false}"},
                        Case{"cylinder-through", 0.040, 0.030, "{}", "{axial_coupling: false}"}}) {
    const double fem = test_support::AxisymmetricFemForce(c.name);
    const double model = UniformNormalForce(c.shaft_length, c.depth, c.options);
    const double plane = UniformNormalForce(c.shaft_length, c.depth, c.plane_options);
    std::printf("%-22s FEM %8.1f N  elastic model %8.1f N  %+.2f %%  plane sections %+.2f %%\n",
                c.name, fem, model, 100 * (model / fem - 1), 100 * (plane / fem - 1));
    EXPECT_LT(std::abs(model / fem - 1.0), 0.01) << c.name;
    if (c.shaft_length == c.depth) {
      EXPECT_NEAR(plane, model, 1e-6 * model) << c.name;
    } else {
      EXPECT_LT(std::abs(model / fem - 1.0), 0.1 * std::abs(plane / fem - 1.0)) << c.name;
    }
    ChartRow("FITFEEL_FEM_AXISYMMETRIC_CSV", c.name, fem, model, plane);
  }
}

// tools/fem/data/solid.csv: CalculiX in 3-D (solid_cases.h), each part held only against rigid
// motion. Where the contact is partial the sections' loads change along the axis (for n = 1, net
// radial loads that balance only over the length), which the parts carry by deforming along their
// axes in every order (axial_coupling.h). Returns the model's error against the FEM (with the
// model's `options`); prints it and the paper law's.
double SolidCaseError(const char* name, const char* options = "{}") {
  const SolidCase c(name);
  const double model = SolidCaseElasticForce(c, options);
  const double paper =
      PaperLawNormalForce([&](int i, int j) { return c.ShaftDeviation(i, j); }, 0.020, 0.020);
  const double fem = c.fem_force;
  std::printf("%-20s FEM %8.1f N  elastic model %8.1f N %+6.2f %%  paper law %8.1f N %+6.2f %%\n",
              name, fem, model, 100 * (model / fem - 1), paper, 100 * (paper / fem - 1));
  // Per mm of the 20 mm engagement, as the sections' rows of the same chart.
  if (std::string(options) == "{}") {
    ChartRow("FITFEEL_FEM_ACCURACY_CSV", name, fem / 20, model / 20, paper / 20);
  }
  return model / fem - 1.0;
}

// Every 3-D case: the uniform press fit (the 3-D mesh against the axisymmetric one too), the
// bent shaft in full contact (the bend's order-1 load adds nothing to the normal force, in the
// FEM to seven digits), on a clearance touching in three short bands, and in partial contact all
// along; an ovality and three lobes growing from nothing in the middle to the ends. Measured:
// within 2.2 % (the paper law: -34 to +4 %). Asserted: 5 % (the issue asks 10).
TEST(ElasticLaw, AgreesWithCalculixInThreeDimensions) {
  EXPECT_NEAR(test_support::FemValue("solid.csv", "uniform-flush", 4) /
                  test_support::AxisymmetricFemForce("cylinder-flush"),
              1.0, 0.005);
  for (const std::string& name : SolidCaseNames()) {
    EXPECT_LT(std::abs(SolidCaseError(name.c_str())), 0.05) << name;
  }
}

// What the orders' coupling along the axis buys, on the same cases: with the breathing mode alone
// (axial_orders: 0; each section's other orders on their own, order 1 about its centroid) the
// bent shaft in partial contact all along is 13 % too stiff (the parts do not bend along their
// axes) and the ovality growing along the axis carries half the FEM's force (each section
// ovalizes on its own at K_2 = 0.145 P0, where a tube that stays round in the middle resists
// ovalizing at its ends); with order 1 alone coupled the bend comes right and the ovality not;
// ovality and three lobes need their own orders.
TEST(ElasticLaw, EachOrdersCouplingIsWhatItsCaseNeeds) {
  EXPECT_GT(SolidCaseError("bent-partial", "{axial_orders: 0}"), 0.10);
  EXPECT_LT(SolidCaseError("oval-ends-partial", "{axial_orders: 0}"), -0.40);
  EXPECT_LT(SolidCaseError("lobed3-ends-partial", "{axial_orders: 0}"), -0.10);
  EXPECT_LT(std::abs(SolidCaseError("bent-partial", "{axial_orders: 1}")), 0.05);
  EXPECT_LT(SolidCaseError("oval-ends-partial", "{axial_orders: 1}"), -0.40);
  EXPECT_LT(std::abs(SolidCaseError("oval-ends-partial", "{axial_orders: 2}")), 0.05);
  EXPECT_LT(SolidCaseError("lobed3-ends-partial", "{axial_orders: 2}"), -0.10);
  EXPECT_LT(std::abs(SolidCaseError("lobed3-ends-partial", "{axial_orders: 3}")), 0.05);
}

// The shaft (20 mm long, the rest of it outside the entrance) part way in: the hub's unloaded
// length and the shaft's length still outside stiffen the loaded band. Plane sections give 10 to
// 78 % too little; with both parts' axial coupling (axial_coupling.h) the model is within
// +0.15 % (half a millimetre, 1 and 2 mm, a quarter, half and three quarters of the 20 mm hub;
// walls of 2, 5 and 10 mm). Asserted: 1 % (the issue asks 10).
struct PartlyEngaged {
  const char* name;
  double depth, hub_diameter;
};

void ExpectWithinOfCalculix(const PartlyEngaged& c, double tolerance, double shaft_row = 0.5e-3) {
  const double fem = test_support::AxisymmetricFemForce(c.name);
  const double coupled = UniformNormalForce(0.020, c.depth, "{}", c.hub_diameter, shaft_row);
  const double plane =
      UniformNormalForce(0.020, c.depth, "{axial_coupling: false}", c.hub_diameter, shaft_row);
  std::printf("%-32s FEM %8.1f N  coupled %8.1f N %+6.2f %%  plane sections %8.1f N %+6.2f %%\n",
              c.name, fem, coupled, 100 * (coupled / fem - 1), plane, 100 * (plane / fem - 1));
  EXPECT_LT(std::abs(coupled / fem - 1.0), tolerance) << c.name;
  EXPECT_LT(plane, fem) << c.name;  // what the coupling is for
  if (shaft_row == 0.5e-3) ChartRow("FITFEEL_FEM_AXISYMMETRIC_CSV", c.name, fem, coupled, plane);
}

TEST(ElasticLaw, AgreesWithCalculixOnAPartlyEngagedHub) {
  for (const PartlyEngaged& c : {PartlyEngaged{"cylinder-entry-2mm", 0.002, 0.030},
                                 PartlyEngaged{"cylinder-quarter-engaged", 0.005, 0.030},
                                 PartlyEngaged{"cylinder-half-engaged", 0.010, 0.030},
                                 PartlyEngaged{"cylinder-three-quarters-engaged", 0.015, 0.030},
                                 PartlyEngaged{"cylinder-thin-hub-half-engaged", 0.010, 0.024},
                                 PartlyEngaged{"cylinder-thick-hub-half-engaged", 0.010, 0.040}}) {
    ExpectWithinOfCalculix(c, 0.01);
  }
}

// Where a press fit starts: half a millimetre in, the FEM's force is 4.5 times what plane sections
// give (4154 against 916 N). A model of the hub's axial coupling alone (a shell on its Lame
// foundation) is 29 % low here: the shaft's length outside the entrance stiffens it as much.
// Also on the shipped scenes' grid, shaft rows of 1 mm against bore rows of 0.5 mm: half a
// millimetre in, the section covers half of the shaft's first row, which the coupling loads
// alone (it splits each part's rows to the shortest row of either); on whole rows it would be
// 27 % low.
TEST(ElasticLaw, AgreesWithCalculixInTheFirstMillimetre) {
  for (const PartlyEngaged& c : {PartlyEngaged{"cylinder-entry-0.5mm", 0.0005, 0.030},
                                 PartlyEngaged{"cylinder-entry-1mm", 0.001, 0.030}}) {
    ExpectWithinOfCalculix(c, 0.01);
    ExpectWithinOfCalculix(c, 0.01, 1e-3);
  }
}

// At the tables' depth steps the pressure map solves the tables' own sections: its integral over
// the shaft's cells is the tables' normal force, at the entry too.
TEST(ElasticLaw, PressureMapCarriesTheTablesNormalForce) {
  const PartSpec shaft = MakeShaft(0.020, 0.020);
  const PartSpec bushing = MakeBushing(0.020, 0.020, 0.030);
  const ModelSettings settings = Elastic(TextureMode::kSampled);
  CylinderContactAnalyzer analyzer;
  analyzer.Prepare(shaft, MakeSms(MakeGrid(20, 72, 0.020, 0.020), [](int, int) { return 5 * kUm; }),
                   bushing, MakeSms(MakeGrid(40, 72, 0.020, 0.020), [](int, int) { return 0.0; }),
                   settings);
  const double cell_area = kPi * 0.020 * 1e-3 / 72;  // the shaft's cells: 1 mm x 1/72 turn
  auto map_force = [&](double depth) {
    MatingPose pose;
    pose.depth = depth;
    Eigen::VectorXd p;
    EXPECT_TRUE(analyzer.PressureMap(pose, &p));
    return p.sum() * cell_area;
  };
  for (double depth : {0.5e-3, 1e-3, 2e-3, 10e-3}) {
    ContactState state;
    MatingPose pose;
    pose.depth = depth;
    analyzer.Evaluate(pose, &state);
    EXPECT_NEAR(map_force(depth), state.normal_force, 1e-3 * state.normal_force) << depth;
  }
}

// The parts' elements are solved only for a table that needs them: a clearance fit's prepare
// leaves them unsolved (on the paper's 20 mm pair they are a third of an H7/g6 scene's prepare),
// an interfering one solves them, and the pressure map of the clearance fit solves its own.
TEST(ElasticLaw, OnlyAnInterferingTableSolvesThePartsElements) {
  const PartSpec shaft = MakeShaft(0.020, 0.020);
  const PartSpec bushing = MakeBushing(0.020, 0.020, 0.030);
  const ModelSettings settings = Elastic(TextureMode::kSampled);
  const SurfaceGrid grid = MakeGrid(40, 72, 0.020, 0.020);
  const SkinModelShape bore = MakeSms(grid, [](int, int) { return 0.0; });
  CylinderContactAnalyzer clear, tight;
  clear.Prepare(shaft, MakeSms(grid, [](int, int) { return -5 * kUm; }), bushing, bore, settings);
  tight.Prepare(shaft, MakeSms(grid, [](int, int) { return 5 * kUm; }), bushing, bore, settings);
  EXPECT_FALSE(clear.axial_elements_solved());
  EXPECT_TRUE(tight.axial_elements_solved());
  MatingPose pose;
  pose.depth = 10e-3;
  Eigen::VectorXd p;
  ASSERT_TRUE(clear.PressureMap(pose, &p));
  EXPECT_TRUE(p.allFinite());
  EXPECT_FALSE(clear.axial_elements_solved());  // its own, not the analyzer's
  // Prepared again as a press fit, the same analyzer solves them.
  clear.Prepare(shaft, MakeSms(grid, [](int, int) { return 5 * kUm; }), bushing, bore, settings);
  EXPECT_TRUE(clear.axial_elements_solved());
}

// With held faces (`section: plane_strain`) the coupling's X is not negative semidefinite (a band
// can expand axially into its unloaded neighbours), so its iteration has no contraction argument:
// it still settles. Partly engaged it carries more than the plane-strain sections, rising with
// the depth (measured 6 249 N half a millimetre in against 1 007; free faces 4 160); fully
// engaged, exactly the sections' (a uniform load shifts nothing).
TEST(ElasticLaw, HeldFacesCoupleToo) {
  double last = 0.0;
  for (double depth : {0.0005, 0.001, 0.002, 0.005, 0.010, 0.015}) {
    const double held = UniformNormalForce(0.020, depth, "{section: plane_strain}");
    const double sections =
        UniformNormalForce(0.020, depth, "{section: plane_strain, axial_coupling: false}");
    EXPECT_TRUE(std::isfinite(held)) << depth;
    EXPECT_GT(held, sections) << depth;
    EXPECT_GT(held, last) << depth;
    last = held;
  }
  const double full = UniformNormalForce(0.020, 0.020, "{section: plane_strain}");
  EXPECT_NEAR(full,
              UniformNormalForce(0.020, 0.020, "{section: plane_strain, axial_coupling: false}"),
              1e-6 * full);
}

}  // namespace
}  // namespace fitfeel::cylindrical
