// Runs the real `fitfeel sms` binary on test/sms_scene.yaml (paper Table 2). The scene's device is
// the registry's test device, found through FITFEEL_PLUGIN_PATH; the cylindrical plugin comes from
// the build tree's plugin folder.
#include <cstdio>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ::fitfeel::test_support::CliOptions;
using ::fitfeel::test_support::CliResult;
using ::fitfeel::test_support::ReadText;
using ::fitfeel::test_support::ShellQuote;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kSource = FITFEEL_TEST_SOURCE_DIR;
const fs::path kBuild = FITFEEL_TEST_BUILD_DIR;
const fs::path kScene = kSource / "surfaces/cylindrical/test/sms_scene.yaml";

fs::path EmptyFolder(const std::string& name) {
  return ::fitfeel::test_support::EmptyFolder("fitfeel_sms_test", name);
}

// `fitfeel sms <scene> <arguments>` (shell text) in `cwd`, with the registry's test device.
CliResult Sms(const std::string& arguments, const fs::path& cwd, const fs::path& scene = kScene) {
  return ::fitfeel::test_support::RunFitfeel(
      "sms " + ShellQuote(scene.string()) + " " + arguments,
      CliOptions().In(cwd).WithPluginPath((kBuild / "test-plugins/good").string()));
}

int Lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(SmsCommand, WritesTheShapeAndReportsEveryCharacteristicBesideItsSpec) {
  const fs::path dir = EmptyFolder("write");
  const CliResult r = Sms("--part shaft -o shaft.csv --seed 5", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("grid 48 x 48 = 2304 cells (auto)"));
  for (const char* name :
       {"two_point_size_min", "two_point_size_max", "axis_straightness", "roundness"}) {
    EXPECT_THAT(r.out, HasSubstr(name));
  }
  EXPECT_THAT(r.out, HasSubstr("pass"));
  EXPECT_THAT(r.out, Not(HasSubstr("FAIL")));
  EXPECT_THAT(r.out, Not(HasSubstr("bushing")));
  const std::string csv = ReadText(dir / "shaft.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "row,column,axial_mm,angle_deg,x_mm,y_mm,z_mm,area_mm2,v_um,v_dimension_um,"
            "v_form_um,v_surface_um");
  EXPECT_EQ(Lines(csv), 1 + 48 * 48);
  // Nothing else in the folder (the temporary file was renamed).
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  // Same seed, same file; another seed, another shape.
  ASSERT_EQ(Sms("--part shaft -o again.csv --seed 5", dir).exit_code, 0);
  EXPECT_EQ(ReadText(dir / "again.csv"), csv);
  ASSERT_EQ(Sms("--part shaft -o other.csv --seed 6", dir).exit_code, 0);
  EXPECT_NE(ReadText(dir / "other.csv"), csv);
}

TEST(SmsCommand, ReportsBothPartsWithoutPart) {
  const CliResult r = Sms("", EmptyFolder("both"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("part 'shaft'"));
  EXPECT_THAT(r.out, HasSubstr("part 'bushing'"));
  EXPECT_THAT(r.out, HasSubstr("grid 16 x 48"));
}

TEST(SmsCommand, UserErrorsExitTwoAndWriteNothing) {
  const fs::path dir = EmptyFolder("errors");
  CliResult r = Sms("--part crank", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("no part 'crank'"));
  r = Sms("-o both.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--part"));
  r = Sms("--part shaft -o missing/shaft.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("does not exist"));
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(SmsCommand, BadModelOptionIsRefusedAtItsKey) {
  const fs::path dir = EmptyFolder("options");
  std::string text = ReadText(kScene);
  const std::string good = "size_draw: per_part";
  ASSERT_NE(text.find(good), std::string::npos);
  text.replace(text.find(good), good.size(), "size_draw: per_row");
  const fs::path scene = dir.parent_path() / "bad_options.yaml";
  {
    std::FILE* f = std::fopen(scene.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(text.c_str(), f);
    std::fclose(f);
  }
  const CliResult r = Sms("", dir, scene);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("model.options.size_draw"));
  EXPECT_THAT(r.err, HasSubstr("per_part"));
}

}  // namespace
