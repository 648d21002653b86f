// The reference paper's headline (docs/paper.md, section 4), as orderings that hold whatever the
// contact model's magnitudes: the comparison method VE1 cannot tell fits apart (it renders the
// Coulomb friction of the shaft's weight, mu W, whatever the geometry); the clearance fit H7/g6
// never renders less than that friction and departs from it only upward, where its parts touch;
// the transition fit H7/js6 is heavier to assemble than H7/g6, which stays nearer VE1 than H7/js6
// does. Runs the shipped scenarios through the real CLI over a few seeds (a seed draws a pair).
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;
using test_support::EmptyFolder;
using test_support::ReadText;
using test_support::RunFitfeel;
using test_support::ShellQuote;

// Table 2 of the paper, as the scenarios carry it: mu = 0.15 and a 2 N shaft weight as the radial
// load, so the friction of the weight alone is 0.3 N.
constexpr double kWeightFriction = 0.15 * 2.0;
// The constrained stage settles a loaded part until the sideways push is below 1 % of the load
// (README, "Quasi-static radial equilibrium"), so the weight's friction is met to that fraction.
constexpr double kSettling = 1e-2;
constexpr int kSeeds = 3;

// A tick of the constrained stage: its axial resistance |fy|.
struct Tick {
  double axial = 0.0;
};

std::vector<Tick> ConstrainedTicks(const std::string& scenario, int seed) {
  const fs::path file = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / (scenario + ".yaml");
  const fs::path out = EmptyFolder("paper-headline", scenario + "-" + std::to_string(seed));
  const auto run = RunFitfeel("run " + ShellQuote(file.string()) + " --seed " +
                              std::to_string(seed) + " --out " + ShellQuote(out.string()));
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  std::istringstream trace(ReadText(out / "trace.csv"));
  std::string line;
  std::getline(trace, line);
  std::vector<std::string> header;
  {
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) header.push_back(cell);
  }
  auto column = [&header](const std::string& name) {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (header[k] == name) return k;
    }
    ADD_FAILURE() << "trace.csv has no column " << name;
    return std::size_t{0};
  };
  const std::size_t stage = column("stage"), fy = column("fy_N");
  std::vector<Tick> ticks;
  while (std::getline(trace, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (cells.size() != header.size() || cells[stage] != "constrained") continue;
    ticks.push_back({std::abs(std::stod(cells[fy]))});
  }
  EXPECT_GT(ticks.size(), 1000u) << scenario << " seed " << seed << ": too short a mating stage";
  return ticks;
}

double MeanAxial(const std::vector<Tick>& ticks) {
  double sum = 0.0;
  for (const Tick& t : ticks) sum += t.axial;
  return ticks.empty() ? 0.0 : sum / ticks.size();
}

TEST(PaperHeadline, TransitionFitIsHeavierAndClearanceFitStaysNearVe1) {
  double js6_sum = 0.0, g6_sum = 0.0, ve1_sum = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const auto js6 = ConstrainedTicks("paper-case1-h7js6", seed);
    const auto g6 = ConstrainedTicks("paper-case1-h7g6", seed);
    const auto ve1 = ConstrainedTicks("paper-case1-ve1", seed);
    js6_sum += MeanAxial(js6);
    g6_sum += MeanAxial(g6);
    ve1_sum += MeanAxial(ve1);
    // The stick-slip junctions start unloaded at first contact and break away within their
    // presliding displacement (2 um), less than one tick's advance at 10 mm/s (10 um): from the
    // second constrained tick on, the part slides.
    ASSERT_EQ(ve1.front().axial, 0.0) << "the first contact starts from unloaded junctions";
    for (std::size_t k = 1; k < ve1.size(); ++k) {
      ASSERT_NEAR(ve1[k].axial, kWeightFriction, 1e-6 * kWeightFriction)
          << "VE1 renders the weight's friction whatever the parts (seed " << seed << ")";
    }
    // The weight always presses the shaft on the bore: its friction is a floor for both fits.
    for (const auto* ticks : {&g6, &js6}) {
      for (std::size_t k = 1; k < ticks->size(); ++k) {
        ASSERT_GE((*ticks)[k].axial, kWeightFriction * (1.0 - kSettling)) << "seed " << seed;
      }
    }
  }
  EXPECT_GT(js6_sum, g6_sum) << "H7/js6 must be heavier to assemble than H7/g6 over " << kSeeds
                             << " part pairs";
  EXPECT_LT(std::abs(g6_sum - ve1_sum), std::abs(js6_sum - ve1_sum))
      << "the clearance fit must stay nearer the ideal-geometry baseline than the transition fit";
}

}  // namespace
}  // namespace fitfeel
