// `fitfeel study` as a user runs it: the files and their columns, byte-identical pairs.csv for one
// and two threads, located refusals with exit code 2 and nothing written.
#include <filesystem>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/testing/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using fitfeel::test_support::CliOptions;
using fitfeel::test_support::EmptyFolder;
using fitfeel::test_support::ReadText;
using fitfeel::test_support::RunFitfeel;
using fitfeel::test_support::ShellQuote;
using ::testing::HasSubstr;

const std::string kStudyScene =
    (fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios/paper-case1-h7js6.yaml").string();

TEST(StudyCommand, WritesPairsAndStudyIdenticalForOneAndTwoThreads) {
  const fs::path dir = EmptyFolder("fitfeel_study_command", "threads");
  const auto one =
      RunFitfeel("study " + ShellQuote(kStudyScene) + " --pairs 6 --seed 3 --threads 1 " +
                 "--out " + ShellQuote((dir / "one").string()));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto two =
      RunFitfeel("study " + ShellQuote(kStudyScene) + " --pairs 6 --seed 3 --threads 2 " +
                 "--out " + ShellQuote((dir / "two").string()));
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const std::string a = ReadText(dir / "one/pairs.csv");
  EXPECT_EQ(a, ReadText(dir / "two/pairs.csv"));
  std::istringstream lines(a);
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("pair,seed,shaft_size_um,hole_size_um,min_clearance_um,interfering,"
                         "axial_mean_N,axial_max_N,radial_max_N",
                         0),
            0u);
  int rows = 0;
  for (std::string line; std::getline(lines, line);) ++rows;
  EXPECT_EQ(rows, 6);

  const auto j = nlohmann::json::parse(ReadText(dir / "one/study.json"));
  EXPECT_EQ(j.at("scenario"), "paper-case1-h7js6");
  EXPECT_EQ(j.at("pairs"), 6);
  EXPECT_EQ(j.at("seed"), 3);
  const double p = j.at("probability_of_interference").get<double>();
  EXPECT_GE(p, 0.0);
  EXPECT_LE(p, 1.0);
  for (const char* key : {"axial_mean_N", "axial_max_N"}) {
    const auto& d = j.at(key);
    EXPECT_LE(d.at("p5").get<double>(), d.at("p25").get<double>());
    EXPECT_LE(d.at("p25").get<double>(), d.at("p50").get<double>());
    EXPECT_LE(d.at("p50").get<double>(), d.at("p75").get<double>());
    EXPECT_LE(d.at("p75").get<double>(), d.at("p95").get<double>());
  }
  EXPECT_THAT(one.out, HasSubstr("6 of 6 pairs"));
  // The chart of the distribution: a PNG file.
  EXPECT_EQ(ReadText(dir / "one/study.png").substr(1, 3), "PNG");
}

TEST(StudyCommand, RefusesBadArgumentsAndWritesNothing) {
  const fs::path dir = EmptyFolder("fitfeel_study_command", "refusals");
  const std::string out = " --out " + ShellQuote((dir / "o").string());
  EXPECT_EQ(RunFitfeel("study " + ShellQuote(kStudyScene) + " --pairs 0" + out).exit_code, 2);
  EXPECT_EQ(RunFitfeel("study " + ShellQuote(kStudyScene) + " --threads 0" + out).exit_code, 2);
  for (const char* seed : {"-1", "''", "18446744073709551616", "1.5"}) {
    const auto r =
        RunFitfeel("study " + ShellQuote(kStudyScene) + " --pairs 1 --seed " + seed + out);
    EXPECT_EQ(r.exit_code, 2) << seed;
    EXPECT_THAT(r.err, HasSubstr("--seed")) << seed;
  }
  EXPECT_EQ(RunFitfeel("study " + ShellQuote(kStudyScene) + " --pairs 1 --out /dev/null").exit_code,
            2);
  const auto missing = RunFitfeel("study no-such.yaml --pairs 2" + out);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("no-such.yaml"));
  EXPECT_FALSE(fs::exists(dir / "o"));
}

}  // namespace
