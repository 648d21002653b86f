// The study's pieces without the CLI: pair seeds, percentiles, the pair geometry on synthetic
// skin model shapes with known answers, and a small study of the paper's case on the real plugins
// (thread-count independence, interruption).
#include "framework/study/study.h"

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "framework/plot/study_chart.h"
#include "framework/plugin/registry.h"
#include "framework/study/pair_geometry.h"
#include "framework/study/study_record.h"

namespace fitfeel::study {
namespace {

namespace fs = std::filesystem;

TEST(PairSeed, DeterministicAndDistinct) {
  EXPECT_EQ(PairSeed(1, 0), PairSeed(1, 0));
  std::set<std::uint64_t> seen;
  for (std::uint64_t s = 0; s < 4; ++s) {
    for (int i = 0; i < 1000; ++i) seen.insert(PairSeed(s, i));
  }
  EXPECT_EQ(seen.size(), 4000u);  // neighbouring study seeds give unrelated pairs
}

// Every pair's seed, as pairs.csv writes it, is a seed run.seed and --seed take (so that one pair
// of a study can be run and watched on its own).
TEST(PairSeed, EveryPairSeedParsesBack) {
  int past_63_bits = 0;
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t seed = PairSeed(1, i);
    EXPECT_EQ(ParseSeed(std::to_string(seed)), seed);
    past_63_bits += seed >> 63 != 0 ? 1 : 0;
  }
  EXPECT_GT(past_63_bits, 400);  // the range this needs
}

TEST(Describe, InterpolatesBetweenOrderStatistics) {
  // 1..10 shuffled: NumPy's default percentiles of 1..10 are p5 1.45, p25 3.25, p50 5.5,
  // p75 7.75, p95 9.55.
  const Distribution d = Describe({7, 3, 10, 1, 5, 9, 2, 8, 4, 6});
  EXPECT_DOUBLE_EQ(d.p5, 1.45);
  EXPECT_DOUBLE_EQ(d.p25, 3.25);
  EXPECT_DOUBLE_EQ(d.p50, 5.5);
  EXPECT_DOUBLE_EQ(d.p75, 7.75);
  EXPECT_DOUBLE_EQ(d.p95, 9.55);
  EXPECT_DOUBLE_EQ(d.mean, 5.5);
  const Distribution one = Describe({2.5});
  EXPECT_EQ(one.p5, 2.5);
  EXPECT_EQ(one.p95, 2.5);
}

// A cylinder grid of `rows` x `columns` cells at `radius`, with V(i, j) from `v`.
template <typename F>
SkinModelShape Cylinder(double radius, int rows, int columns, F v, double size) {
  SkinModelShape s;
  SurfaceGrid& g = s.grid;
  g.rows = rows;
  g.columns = columns;
  g.row_position = Eigen::VectorXd::LinSpaced(rows, 0.0, 0.02);
  g.column_angle.resize(columns);
  g.centre.resize(3, rows * columns);
  s.variation.resize(rows * columns);
  s.dimension_part = Eigen::VectorXd::Constant(rows * columns, size / 2.0);
  for (int j = 0; j < columns; ++j) g.column_angle(j) = 2.0 * std::numbers::pi * j / columns;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const double a = g.column_angle(j);
      g.centre.col(g.index(i, j)) << radius * std::cos(a), g.row_position(i), radius * std::sin(a);
      s.variation(g.index(i, j)) = v(i, a);
    }
  }
  return s;
}

TEST(MeasurePair, UniformSizesGiveTheSizeClearance) {
  const auto shaft = Cylinder(
      0.01, 5, 36, [](int, double) { return 2e-6; }, 4e-6);
  const auto bore = Cylinder(
      0.01, 5, 36, [](int, double) { return 5e-6; }, 10e-6);
  const PairGeometry g = MeasurePair(shaft, bore);
  EXPECT_NEAR(g.inner_size, 4e-6, 1e-18);
  EXPECT_NEAR(g.outer_size, 10e-6, 1e-18);
  ASSERT_TRUE(g.min_clearance.has_value());
  EXPECT_NEAR(*g.min_clearance, 6e-6, 1e-15);
}

TEST(MeasurePair, OvalBoreClosesAcrossItsMinorAxis) {
  // Bore 5 + 3 cos 2a um, shaft 2 um: room(a) = 3 + 3 cos 2a, across = 6 + 6 cos 2a, least 0 at
  // a = pi/2 (a column of the 36-column grid).
  const auto shaft = Cylinder(
      0.01, 4, 36, [](int, double) { return 2e-6; }, 4e-6);
  const auto bore = Cylinder(
      0.01, 4, 36, [](int, double a) { return 5e-6 + 3e-6 * std::cos(2 * a); }, 10e-6);
  ASSERT_TRUE(MeasurePair(shaft, bore).min_clearance.has_value());
  EXPECT_NEAR(*MeasurePair(shaft, bore).min_clearance, 0.0, 1e-15);
}

TEST(MeasurePair, EveryRowOfTheShaftPassesEveryRowOfTheBore) {
  // A bump on the shaft's last row at a = 0 and a narrowing at the bore's first row at a = pi:
  // the rigid insertion meets both across one diameter: 2*(5 - 2) - 1 - 2 = 3 um.
  const auto shaft = Cylinder(
      0.01, 4, 36, [](int i, double a) { return 2e-6 + (i == 3 && a == 0.0 ? 1e-6 : 0.0); }, 4e-6);
  const auto bore = Cylinder(
      0.01, 4, 36,
      [](int i, double a) {
        return 5e-6 - (i == 0 && std::abs(a - std::numbers::pi) < 1e-9 ? 2e-6 : 0.0);
      },
      10e-6);
  EXPECT_NEAR(*MeasurePair(shaft, bore).min_clearance, 3e-6, 1e-15);
}

TEST(MeasurePair, NoClearanceForOtherSurfaces) {
  auto flat = Cylinder(
      0.01, 3, 8, [](int, double) { return 0.0; }, 0.0);
  flat.grid.centre.row(0).setLinSpaced(0.0, 1.0);  // not on one radius
  EXPECT_FALSE(MeasurePair(flat, flat).min_clearance.has_value());
}

class PaperStudy : public ::testing::Test {
 protected:
  PaperStudy() : registry_({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"}) { registry_.LoadAll(); }
  const fs::path scene_ = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios/paper-case1-h7js6.yaml";
  PluginRegistry registry_;
};

// A nut on a bolt is no fit: its pitch diameters would read as a shaft and a hole. Refused, saying
// what to run instead.
TEST_F(PaperStudy, RefusesAScrewJoint) {
  StudySettings settings;
  settings.pairs = 2;
  try {
    RunStudy(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios/bolt-m10.yaml", registry_, settings);
    FAIL() << "a thread scene was studied";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "surface");
    EXPECT_NE(std::string(e.what()).find("bolt-m10.yaml:7:10: surface: expected a surface whose "
                                         "pairs a fit study compares"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("fitfeel run FILE --seed S"), std::string::npos);
  }
}

TEST_F(PaperStudy, SamePairsWhateverTheThreadCount) {
  StudySettings one;
  one.pairs = 4;
  one.seed = 7;
  StudySettings two = one;
  two.threads = 2;
  const StudyResult a = RunStudy(scene_, registry_, one);
  const StudyResult b = RunStudy(scene_, registry_, two);
  ASSERT_EQ(a.pairs.size(), 4u);
  EXPECT_FALSE(a.interrupted);
  EXPECT_EQ(PairsCsv(a), PairsCsv(b));
  // Different pairs are different parts.
  EXPECT_NE(a.pairs[0].shaft_size_um, a.pairs[1].shaft_size_um);
  for (const PairResult& p : a.pairs) {
    // The paper's parts stay within their drawing: shaft -8/+8 um, hole 0/+25 um.
    EXPECT_GE(p.shaft_size_um, -8.0);
    EXPECT_LE(p.shaft_size_um, 8.0);
    EXPECT_GE(p.hole_size_um, 0.0);
    EXPECT_LE(p.hole_size_um, 25.0);
    ASSERT_TRUE(p.min_clearance_um.has_value());
    // A pair with room everywhere cannot interfere with a centred rigid shaft.
    if (*p.min_clearance_um > 0.0) {
      EXPECT_FALSE(p.interfering) << p.pair;
    }
    EXPECT_GT(p.constrained_ticks, 0);
  }
}

// The first `rows` pairs of data/NAME-seed1-20-pairs.csv: pairs.csv of a 20-pair study of
// scenarios/NAME.yaml, seed 1, with every pair prepared alone on one thread (nothing shared between
// pairs).
std::string ReferenceRows(const std::string& name, int rows) {
  std::ifstream in(fs::path(FITFEEL_TEST_SOURCE_DIR) / "framework/study/test/data" /
                   (name + "-seed1-20-pairs.csv"));
  std::string text, line;
  for (int i = 0; i <= rows && std::getline(in, line); ++i) text += line + '\n';
  return text;
}

// Pairs share what their prepares compute from the scene alone, and run on two threads: every
// row is still byte for byte what the pair computes alone. A transition fit (some pairs interfere,
// so the elastic model's elements are made once and shared) and an interference fit (every pair
// needs them), each from a cold start and on threads racing for the first solve.
TEST_F(PaperStudy, SharedPrepareGivesThePairsOfUnsharedOnes) {
  for (const auto& [name, pairs] : {std::pair{std::string("paper-case1-h7js6"), 20},
                                    std::pair{std::string("fits-20mm-h7n6"), 6}}) {
    for (int threads : {1, 2}) {
      StudySettings s;
      s.pairs = pairs;
      s.threads = threads;
      const StudyResult r = RunStudy(
          fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / (name + ".yaml"), registry_, s);
      EXPECT_EQ(PairsCsv(r), ReferenceRows(name, pairs)) << name << ", " << threads << " threads";
    }
  }
  // And against this build's own unshared path (the shared elements, section solvers and
  // resampling kernels each made by one pair and read by the others): a press fit, and the
  // transition fit's first pairs of another seed.
  StudySettings shared;
  shared.pairs = 4;
  shared.seed = 11;
  shared.threads = 2;
  StudySettings alone = shared;
  alone.share_prepare = false;
  for (const char* name : {"fits-20mm-h7n6.yaml", "paper-case1-h7js6.yaml"}) {
    const fs::path scene = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / name;
    EXPECT_EQ(PairsCsv(RunStudy(scene, registry_, shared)),
              PairsCsv(RunStudy(scene, registry_, alone)))
        << name;
  }
  // One pair alone (the distributed study's task) keeps what it made for the next call.
  EXPECT_EQ(RunStudyPair(scene_, registry_, 1, 3).axial_mean_N,
            RunStudyPair(scene_, registry_, 1, 3).axial_mean_N);
}

TEST_F(PaperStudy, StopLeavesACompletePrefix) {
  std::atomic<bool> stop{false};
  StudySettings s;
  s.pairs = 50;
  s.stop = &stop;
  s.progress = [&stop](int done, int) {
    if (done >= 2) stop = true;
  };
  const StudyResult r = RunStudy(scene_, registry_, s);
  EXPECT_TRUE(r.interrupted);
  ASSERT_GE(r.pairs.size(), 2u);
  EXPECT_LT(r.pairs.size(), 50u);
  for (std::size_t i = 0; i < r.pairs.size(); ++i) EXPECT_EQ(r.pairs[i].pair, static_cast<int>(i));
}

TEST_F(PaperStudy, RefusesBadSettingsBeforeRunning) {
  StudySettings s;
  s.pairs = 0;
  EXPECT_THROW(RunStudy(scene_, registry_, s), UserError);
  s.pairs = 1;
  s.threads = 0;
  EXPECT_THROW(RunStudy(scene_, registry_, s), UserError);
  s.threads = 1;
  EXPECT_THROW(RunStudy("no/such/scene.yaml", registry_, s), UserError);
}

}  // namespace
}  // namespace fitfeel::study

namespace fitfeel::study {
namespace {

TEST(LoadStudy, ReadsWhatWriteStudyWroteAndLocatesBrokenLines) {
  const fs::path dir = fs::path(::testing::TempDir()) / "fitfeel_study_record";
  fs::remove_all(dir);
  StudyResult r;
  r.scenario = "demo";
  r.requested_pairs = 2;
  PairResult a, b;
  a.pair = 0;
  a.axial_mean_N = 0.3;
  a.axial_max_N = 0.5;
  b.pair = 1;
  b.axial_mean_N = 120.0;
  b.axial_max_N = 300.0;
  b.interfering = true;
  r.pairs = {a, b};
  WriteStudy(dir, r);
  const StudyRecord back = LoadStudy(dir);
  EXPECT_EQ(back.scenario, "demo");
  EXPECT_EQ(back.axial_mean_N, (std::vector<double>{0.3, 120.0}));
  EXPECT_EQ(back.axial_max_N, (std::vector<double>{0.5, 300.0}));
  EXPECT_DOUBLE_EQ(back.probability_of_interference, 0.5);

  // The chart: two panels, logarithmic since the pairs span decades, the reference drawn.
  const plot::LineChart chart = plot::MakeStudyChart({back}, plot::ReferenceLine{"VE1", 0.3});
  ASSERT_EQ(chart.panels.size(), 2u);
  EXPECT_TRUE(chart.panels[0].log_y);
  ASSERT_EQ(chart.panels[0].series.size(), 2u);
  EXPECT_EQ(chart.panels[0].series[0].y, (std::vector<double>{0.3, 120.0}));
  EXPECT_EQ(chart.panels[0].series[1].label, "VE1");

  std::ofstream(dir / "pairs.csv", std::ios::app) << "2,1,0,0,,0,abc,1,1,3899,,,0\n";
  try {
    LoadStudy(dir);
    FAIL() << "a broken line was accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("pairs.csv:4:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'abc'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LoadStudy(dir / "missing"), UserError);
}

}  // namespace
}  // namespace fitfeel::study
