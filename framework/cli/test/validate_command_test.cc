// `fitfeel validate` on a shipped fits scene whose device renders as a Touch through the
// perceptual force mapping: it prints the map (knee, exponent, scene top -> device top) and what
// a few scene forces become; a linear scene prints none, and a contradictory safety section is
// refused at its key.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;
using test_support::CliOptions;
using test_support::RunFitfeel;
using ::testing::HasSubstr;
using ::testing::Not;

// scenarios/fits-20mm-h7s6.yaml with `device_keys` added to its device section and `tail`
// appended.
fs::path Scene(const fs::path& dir, const std::string& device_keys, const std::string& tail = "") {
  std::string text = test_support::ReadText(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" /
                                            "fits-20mm-h7s6.yaml");
  const std::string plugin = "  plugin: fitfeel.device.simulated\n";
  text.insert(text.find(plugin) + plugin.size(), device_keys);
  const fs::path file = dir / "scene.yaml";
  std::ofstream(file) << text << tail;
  return file;
}

TEST(ValidateCommand, PrintsThePerceptualMapping) {
  const fs::path dir = test_support::EmptyTestFolder("validate-mapping");
  const fs::path file = Scene(dir, "  model: touch\n  force_mapping: perceptual\n");
  const test_support::CliResult r =
      RunFitfeel(test_support::ShellWords({"validate", file.string()}), CliOptions().In(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // f_top = 0.88 N / sqrt(1 - 1/e); gamma = ln(f_top / 0.1 N) / ln(20 kN / 0.1 N).
  EXPECT_THAT(r.out, HasSubstr("mapping      perceptual: knee 0.1 N, exponent 0.197, scene top "
                               "20000 N -> device top 1.107 N\n"));
  EXPECT_THAT(r.out, HasSubstr("0.3 N -> 0.1242 N, 10 N -> 0.2477 N, 1000 N -> 0.6135 N, "
                               "10000 N -> 0.9656 N\n"));
  EXPECT_THAT(r.out, HasSubstr("valid\n"));
}

TEST(ValidateCommand, TheSafetySectionOverridesTheDevicesMapping) {
  const fs::path dir = test_support::EmptyTestFolder("validate-mapping-safety");
  const fs::path knee = Scene(dir, "  model: touch\n",
                              "safety:\n  force_mapping: perceptual\n  mapping_knee: 0.2 N\n"
                              "  mapping_top: 15 kN\n");
  const test_support::CliResult r =
      RunFitfeel(test_support::ShellWords({"validate", knee.string()}), CliOptions().In(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("perceptual: knee 0.2 N, exponent 0.1524, scene top 15000 N"));

  const fs::path linear = Scene(dir, "  model: touch\n  force_mapping: perceptual\n",
                                "safety:\n  force_scale: 0.0001\n");
  const test_support::CliResult plain =
      RunFitfeel(test_support::ShellWords({"validate", linear.string()}), CliOptions().In(dir));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_THAT(plain.out, Not(HasSubstr("mapping ")));

  const fs::path both =
      Scene(dir, "  model: touch\n", "safety:\n  force_mapping: perceptual\n  force_scale: 0.01\n");
  const test_support::CliResult refused =
      RunFitfeel(test_support::ShellWords({"validate", both.string()}), CliOptions().In(dir));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("safety.force_scale: expected no force_scale with "
                                     "force_mapping: perceptual"));
}

}  // namespace
}  // namespace fitfeel::cli
