#include "framework/plot/gnuplot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "framework/core/error.h"
#include "framework/plot/render.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ScopedEnv;
using testing::ScratchDir;

TEST(ResolveOutputs, PngSvgOrBoth) {
  ScratchDir dir;
  auto png = ResolveOutputs(dir.path() / "a.png");
  ASSERT_EQ(png.size(), 1u);
  EXPECT_EQ(png[0].format, ImageFormat::kPng);
  auto svg = ResolveOutputs(dir.path() / "a.svg");
  ASSERT_EQ(svg.size(), 1u);
  EXPECT_EQ(svg[0].format, ImageFormat::kSvg);
  auto both = ResolveOutputs(dir.path() / "chart");
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].path, dir.path() / "chart.png");
  EXPECT_EQ(both[1].path, dir.path() / "chart.svg");
}

TEST(ResolveOutputs, RefusesUnknownExtension) {
  ScratchDir dir;
  try {
    ResolveOutputs(dir.path() / "chart.jpg");
    FAIL() << "a .jpg output was accepted";
  } catch (const UserError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'.jpg'"));
    EXPECT_THAT(e.what(), HasSubstr("expected .png, .svg"));
  }
}

TEST(ResolveOutputs, RefusesMissingFolderAndEmptyName) {
  ScratchDir dir;
  EXPECT_THROW(ResolveOutputs(dir.path() / "no" / "such" / "x.png"), UserError);
  EXPECT_THROW(ResolveOutputs(""), UserError);
  EXPECT_THROW(ResolveOutputs(dir.path() / ".."), UserError);
}

TEST(QuoteForGnuplot, KeepsTextLiteral) {
  EXPECT_EQ(QuoteForGnuplot("H7/g6"), "'H7/g6'");
  EXPECT_EQ(QuoteForGnuplot("it's"), "'it''s'");
  EXPECT_EQ(QuoteForGnuplot("a\nb\tc"), "'a b c'");
  EXPECT_EQ(QuoteForGnuplot("`rm -rf x`"), "'`rm -rf x`'");
}

TEST(Gnuplot, MissingExecutableNamesThePackage) {
  ScopedEnv env("FITFEEL_GNUPLOT", "/nonexistent/gnuplot");
  EXPECT_FALSE(Gnuplot::Locate().has_value());
  try {
    Gnuplot::Find();
    FAIL() << "a missing gnuplot was accepted";
  } catch (const UnsupportedError& e) {
    EXPECT_THAT(e.what(), HasSubstr("gnuplot-nox"));
  }
}

TEST(Gnuplot, ScriptErrorIsReportedWithGnuplotsMessage) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteFile(dir.path() / "bad.gp", "plot 'no-such-file.dat' using 1:2\n");
  try {
    Gnuplot::Find().Run(dir.path() / "bad.gp", dir.path());
    FAIL() << "a failing script passed";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("no-such-file.dat"));
  }
}

TEST(Gnuplot, WarningsAreErrors) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteFile(dir.path() / "warn.gp", "print 'ok'\nset xrange [1:1]\nplot x\n");
  try {
    Gnuplot::Find().Run(dir.path() / "warn.gp", dir.path());
    FAIL() << "a script with a warning passed";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("range"));
  }
}

TEST(Gnuplot, IgnoresTheUsersInitFile) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  // An init file that would make every run fail; -d must keep gnuplot from reading it.
  testing::WriteFile(dir.path() / ".gnuplot", "this is not gnuplot\n");
  testing::WriteFile(dir.path() / "ok.gp", "a = 1\n");
  testing::ScopedEnv home("HOME", dir.path().c_str());
  EXPECT_NO_THROW(Gnuplot::Find().Run(dir.path() / "ok.gp", dir.path()));
}

TEST(Gnuplot, BackquotesInLabelsAreNotRun) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  const fs::path marker = dir.path() / "injected";
  LineChart chart;
  chart.title = "`touch " + marker.string() + "`";
  chart.panels.push_back({"it's \"quoted\"",
                          "x (mm)",
                          "y (N)",
                          false,
                          false,
                          {{"`touch " + marker.string() + "`", {0.0, 1.0}, {1.0, 2.0}}}});
  Render(chart, ResolveOutputs(dir.path() / "chart.svg"));
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_THAT(testing::ReadFile(dir.path() / "chart.svg"), HasSubstr("`touch "));
}

TEST(InstallAtomically, ReplacesTargetAndLeavesNoTemporary) {
  ScratchDir dir;
  testing::WriteFile(dir.path() / "source", "new bytes");
  testing::WriteFile(dir.path() / "target.png", "old");
  InstallAtomically(dir.path() / "source", dir.path() / "target.png");
  EXPECT_EQ(testing::ReadFile(dir.path() / "target.png"), "new bytes");
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 2);
  struct stat info {};
  ASSERT_EQ(::stat((dir.path() / "target.png").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST(TempDir, IsPrivateAndRemoved) {
  fs::path kept;
  {
    TempDir dir;
    kept = dir.path();
    struct stat info {};
    ASSERT_EQ(::stat(kept.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0700u);
    testing::WriteFile(kept / "file", "x");
  }
  EXPECT_FALSE(fs::exists(kept));
}

}  // namespace
}  // namespace fitfeel::plot
