// `fitfeel fit` on a thread, run as a user runs it: the limits of both parts, the clearance, the
// axial play and the backlash of M10x1.5 6H/6g as ISO 965-2 gives the limits.
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel::cli {
namespace {

using test_support::CliOptions;
using test_support::RunFitfeel;
using ::testing::StartsWith;

// ISO 965-2, M10x1.5: 6H D1 8.376-8.676, D2 9.026-9.206 mm; 6g d 9.732-9.968, d2 8.862-8.994,
// d3 max 8.128 mm. Clearance 32-344 um, play = clearance x tan 30 deg, backlash 2 pi play / P.
TEST(FitCommand, ThreadFitPrintsBothPartsClearancePlayAndBacklash) {
  // clang-format off
  const std::vector<std::string> expected = {
      "ISO 965-1 thread fit M10x1.5 6H/6g  (coarse pitch 1.5 mm, d2 range 5.6-11.2 mm)",
      "  nut  6H",
      "        D1  EI =       0 um   ES =    +300 um   limits 8.376 mm .. 8.676 mm   (tolerance 300 um)",
      "        D2  EI =       0 um   ES =    +180 um   limits 9.026 mm .. 9.206 mm   (tolerance 180 um)",
      "        D   EI =       0 um                     min 10.000 mm",
      "  bolt 6g",
      "        d   ei =    -268 um   es =     -32 um   limits 9.732 mm .. 9.968 mm   (tolerance 236 um)",
      "        d2  ei =    -164 um   es =     -32 um   limits 8.862 mm .. 8.994 mm   (tolerance 132 um)",
      "        d3                    es =     -32 um   max 8.128 mm",
      "  pitch-diameter clearance (D2 - d2): min +32 um, max +344 um",
      "  axial play (clearance x tan 30 deg): min 18.48 um, max 198.61 um",
      "  angular backlash (2 pi play / P): min 4.43 deg, max 47.67 deg",
  };
  // clang-format on
  for (const char* size : {"M10x1.5", "M10"}) {
    const test_support::CliResult r =
        RunFitfeel(std::string("fit ") + size + " 6H/6g",
                   CliOptions().In(test_support::EmptyTestFolder("fit")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(test_support::Lines(r.out), expected) << size;
  }
}

TEST(FitCommand, BadThreadCodesExitWithTwo) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"fit M10x1.3 6H/6g",
       "fit: ISO thread 'M10x1.3 6H': 1.3 mm is not an ISO 261 pitch of M10 (expected one of 1.5 "
       "(coarse), 1.25, 1, 0.75)"},
      {"fit M10 6g/6H",
       "fit: the first class of a thread fit must be an internal thread's (position G or H, e.g. "
       "6H), found '6g'"},
      {"fit M10 6H-6g", "fit: a thread fit is written NUT/bolt (e.g. 6H/6g), found '6H-6g'"},
      {"fit M10 6H/6q", "fit: ISO thread 'M10 6q': expected a tolerance position e, f, g, h"},
  };
  for (const auto& [line, says] : cases) {
    const test_support::CliResult r =
        RunFitfeel(line, CliOptions().In(test_support::EmptyTestFolder("fit")));
    EXPECT_EQ(r.exit_code, 2) << line;
    EXPECT_THAT(r.err, StartsWith("fitfeel: error: " + says)) << line;
  }
}

}  // namespace
}  // namespace fitfeel::cli
