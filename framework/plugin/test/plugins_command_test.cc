// `fitfeel plugins`, run as a user runs it: the built CLI with FITFEEL_PLUGIN_PATH pointing at the
// good test plugin and a broken one.

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/plugin/test/test_plugin_dirs.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

using test_support::BuildDir;
using test_support::CaseDir;

namespace fs = std::filesystem;
using test_support::CliOptions;
using test_support::CliResult;
using ::testing::HasSubstr;

// The build tree: FITFEEL_BUILD_DIR when set (fitfeel_add_test means to set it), else the folder
// above this test binary, which fitfeel_add_test puts in <build>/tests/. The fallback matters:
// gtest_discover_tests keeps only the first variable of a multi-variable ENVIRONMENT property.

// Runs `fitfeel plugins <args>` with the given plugin path; its stderr goes to the test log.
CliResult RunPlugins(const std::string& plugin_path, const std::string& args) {
  CliResult run =
      test_support::RunFitfeel("plugins " + args, CliOptions().WithPluginPath(plugin_path));
  std::cerr << run.err;
  return run;
}

class PluginsCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_FALSE(BuildDir().empty()) << "FITFEEL_BUILD_DIR is not set: run through ctest";
    ASSERT_TRUE(fs::exists(test_support::FitfeelBinary())) << "the fitfeel CLI was not built";
    path_ = CaseDir("good").string() + ":" + CaseDir("wrong_abi").string();
  }
  std::string path_;
};

TEST_F(PluginsCommandTest, ListsPluginsFoldersAndRefusalsAsAlignedText) {
  const CliResult run = RunPlugins(path_, "");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const fs::path good = fs::canonical(CaseDir("good") / "libfitfeel_test_good.so");
  EXPECT_THAT(run.out, HasSubstr("ID"));
  EXPECT_THAT(run.out, HasSubstr("SUMMARY"));
  // id, kind and version in aligned columns on one line, then the library and the limitation.
  EXPECT_THAT(run.out, ::testing::ContainsRegex(
                           "fitfeel\\.test\\.inert_surface +surface +1\\.0\\.0 +Test surface "
                           "type that models nothing"));
  EXPECT_THAT(run.out, ::testing::ContainsRegex(
                           "fitfeel\\.test\\.still_device +device +1\\.0\\.0 +Test device"));
  EXPECT_THAT(run.out, HasSubstr("library: " + good.string()));
  EXPECT_THAT(run.out, HasSubstr("renders no forces: test surface: parses no geometry and has no "
                                 "resistance law"));
  EXPECT_THAT(run.out, HasSubstr("searched, in order:\n  " + CaseDir("good").string() +
                                 " (FITFEEL_PLUGIN_PATH)\n  " + CaseDir("wrong_abi").string() +
                                 " (FITFEEL_PLUGIN_PATH)\n"));
  EXPECT_THAT(run.out, HasSubstr("(build tree)"));
  EXPECT_THAT(run.out, HasSubstr("(install prefix)"));
  EXPECT_THAT(run.out, HasSubstr("libfitfeel_test_wrong_abi.so\n    plugin ABI version mismatch"));
  // Only surfaces that render no forces get a limitation line: the test surface; the devices and
  // the build tree's surfaces have none.
  std::size_t lines = 0;
  for (std::size_t at = run.out.find("renders no forces"); at != std::string::npos;
       at = run.out.find("renders no forces", at + 1)) {
    ++lines;
  }
  EXPECT_EQ(lines, 1u);
}

TEST_F(PluginsCommandTest, JsonListsTheSame) {
  const CliResult run = RunPlugins(path_, "--json");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const nlohmann::json json = nlohmann::json::parse(run.out);
  bool saw_surface = false;
  for (const auto& p : json.at("plugins")) {
    if (p.at("id") == "fitfeel.test.inert_surface") {
      saw_surface = true;
      EXPECT_EQ(p.at("kind"), "surface");
      EXPECT_EQ(p.at("version"), "1.0.0");
      EXPECT_EQ(p.at("renders_forces"), false);
      EXPECT_THAT(p.at("limitation").get<std::string>(), HasSubstr("no resistance law"));
      EXPECT_THAT(p.at("library").get<std::string>(), HasSubstr("libfitfeel_test_good.so"));
    }
  }
  EXPECT_TRUE(saw_surface);
  ASSERT_GE(json.at("search_path").size(), 4u);
  EXPECT_EQ(json.at("search_path")[0].at("path"), CaseDir("good").string());
  EXPECT_EQ(json.at("search_path")[0].at("exists"), true);
  bool saw_refusal = false;
  for (const auto& r : json.at("refused")) {
    if (r.at("library").get<std::string>().find("wrong_abi") != std::string::npos) {
      saw_refusal = true;
      EXPECT_THAT(r.at("reason").get<std::string>(), HasSubstr("ABI version mismatch"));
    }
  }
  EXPECT_TRUE(saw_refusal);
}

// Every test plugin exports exactly one symbol, the hook (or, for no_hook, its misspelling): the
// project builds with hidden visibility, and register.cc must not leak anything else.
TEST(TestPluginSymbolsTest, EachTestPluginExportsOnlyItsHook) {
  ASSERT_FALSE(BuildDir().empty());
  int checked = 0;
  for (const auto& folder : fs::directory_iterator(BuildDir() / "test-plugins")) {
    for (const auto& file : fs::directory_iterator(folder.path())) {
      if (file.path().extension() != ".so") continue;
      const std::string command =
          "nm -D --defined-only '" + file.path().string() + "' | awk '{print $3}'";
      FILE* pipe = popen(command.c_str(), "r");
      ASSERT_NE(pipe, nullptr);
      std::string out;
      std::array<char, 4096> buffer{};
      std::size_t n = 0;
      while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        out.append(buffer.data(), n);
      ASSERT_EQ(pclose(pipe), 0) << command;
      const std::string expected = folder.path().filename() == "no_hook"
                                       ? "fitfeel_register_plugin\n"
                                       : "fitfeel_plugin_register\n";
      EXPECT_EQ(out, expected) << file.path();
      ++checked;
    }
  }
  EXPECT_GE(checked, 14);
}

}  // namespace
}  // namespace fitfeel
