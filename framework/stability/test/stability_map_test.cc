#include "framework/stability/stability_map.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

using ::fitfeel::test_support::Lines;
using ::fitfeel::test_support::ReadText;

TEST(LogSpaced, CoversTheRangeEvenly) {
  const std::vector<double> v = LogSpaced(100.0, 1e5, 4);
  ASSERT_EQ(v.size(), 13u);
  EXPECT_DOUBLE_EQ(v.front(), 100.0);
  EXPECT_DOUBLE_EQ(v.back(), 1e5);
  for (std::size_t i = 1; i < v.size(); ++i)
    EXPECT_NEAR(v[i] / v[i - 1], std::pow(10.0, 0.25), 1e-12);
  EXPECT_EQ(LogSpaced(5.0, 5.0, 3), std::vector<double>{5.0});
  EXPECT_THROW(LogSpaced(0.0, 10.0, 3), UserError);
  EXPECT_THROW(LogSpaced(10.0, 1.0, 3), UserError);
  EXPECT_THROW(LogSpaced(1.0, 10.0, 0), UserError);
}

TEST(StabilityMap, OneRowPerCombinationAndTheBoundAgrees) {
  StabilityMapSettings s;
  s.base.spec = LookupDeviceSpec("PHANTOM Desktop");
  s.base.horizon = 1.0;
  s.rates = {500.0, 1000.0};
  s.dampings = {-1.0, 0.0};
  s.stiffnesses = LogSpaced(1e3, 1e5, 3);
  const std::vector<StabilityMapRow> rows = SweepStabilityMap(s);
  ASSERT_EQ(rows.size(), 2u * 2u * 2u * s.stiffnesses.size());
  const double b = s.base.spec.damping;
  for (const StabilityMapRow& r : rows) {
    const double margin = b - (r.stiffness / r.rate / 2.0 + std::abs(r.damping));
    EXPECT_EQ(r.outcome.bound_ok, margin > 0.0);
    EXPECT_LE(r.outcome.peak_force, s.base.spec.max_force);
    if (r.method == RenderingMethod::kCoupled) {
      EXPECT_TRUE(r.outcome.stable) << r.rate << " " << r.stiffness;
    } else if (margin > 0.2 * b) {
      EXPECT_TRUE(r.outcome.stable) << r.rate << " " << r.stiffness;
    } else if (margin < -0.25 * (b - std::abs(r.damping))) {
      EXPECT_FALSE(r.outcome.stable) << r.rate << " " << r.stiffness;
    }
  }
  const std::vector<std::string> lines = Lines(StabilityMapCsv(rows));
  ASSERT_EQ(lines.size(), rows.size() + 1);
  EXPECT_EQ(lines[0],
            "method,rate_Hz,stiffness_N_per_m,damping_Ns_per_m,bound_ok,stable,energy_growth_J,"
            "peak_force_N");
  EXPECT_EQ(lines[1].rfind("direct,500,1000,-1,1,1,", 0), 0u) << lines[1];
  EXPECT_EQ(lines.back().rfind("coupled,1000,100000,0,0,1,", 0), 0u) << lines.back();
}

TEST(StabilityMap, EmptyAxisIsRefused) {
  StabilityMapSettings s;
  s.base.spec = LookupDeviceSpec("Touch");
  s.rates = {1000.0};
  s.dampings = {0.0};
  EXPECT_THROW(SweepStabilityMap(s), UserError);
}

TEST(WriteFileAtomically, ReplacesWholeOrNotAtAll) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("fitfeel_stability_map_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::filesystem::path file = folder / "map.csv";
  WriteFileAtomically(file, "first\n");
  EXPECT_EQ(ReadText(file), "first\n");
  WriteFileAtomically(file, "second\n");
  EXPECT_EQ(ReadText(file), "second\n");
  EXPECT_THROW(WriteFileAtomically(folder / "missing" / "map.csv", "x"), UserError);
  EXPECT_THROW(WriteFileAtomically(folder, "x"), UserError);
  EXPECT_EQ(ReadText(file), "second\n");
  // Nothing but the file is left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++entries;
  EXPECT_EQ(entries, 1);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace fitfeel
