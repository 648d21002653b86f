// Runs the real `fitfeel validate` binary on bad scenario files: exit code 2, the precise message
// on stderr, no "valid" on stdout, and no file created anywhere in the working folder.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kSource = FITFEEL_TEST_SOURCE_DIR;
const fs::path kFitfeel = fs::path(FITFEEL_TEST_BUILD_DIR) / "bin" / "fitfeel";

struct Result {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string Slurp(const fs::path& file) {
  std::string text;
  if (FILE* f = std::fopen(file.c_str(), "r")) {
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
  }
  return text;
}

// Runs `fitfeel validate <scenario>` inside an empty folder `cwd`.
Result Validate(const fs::path& scenario, const fs::path& cwd) {
  const fs::path out = cwd.parent_path() / (cwd.filename().string() + ".out");
  const fs::path err = cwd.parent_path() / (cwd.filename().string() + ".err");
  const std::string command = "cd '" + cwd.string() + "' && '" + kFitfeel.string() +
                              "' validate '" + scenario.string() + "' >'" + out.string() + "' 2>'" +
                              err.string() + "'";
  const int status = std::system(command.c_str());
  Result result;
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = Slurp(out);
  result.err = Slurp(err);
  return result;
}

fs::path EmptyFolder(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "fitfeel_validate_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ValidateCommandTest, BadScenarioExitsTwoWithTheMessageAndWritesNothing) {
  if (!fs::exists(kFitfeel)) GTEST_SKIP() << "build the fitfeel target first: " << kFitfeel;
  for (const char* name : {"missing_unit", "yaml_syntax", "nonexistent_plugin"}) {
    const fs::path file = kSource / "framework/scenario/test/bad" / (std::string(name) + ".yaml");
    const fs::path cwd = EmptyFolder(name);
    const Result result = Validate(file, cwd);
    EXPECT_EQ(result.exit_code, 2) << name << ": " << result.err;
    EXPECT_THAT(result.err, HasSubstr("fitfeel: error: " + file.string() + ":")) << name;
    EXPECT_THAT(result.err, HasSubstr(": expected ")) << name;
    EXPECT_THAT(result.out, Not(HasSubstr("valid"))) << name;
    EXPECT_TRUE(fs::is_empty(cwd)) << name << " left files behind";
  }
  // A syntax error is found before any plugin is needed, so the whole message is known here.
  const fs::path cwd = EmptyFolder("syntax");
  const fs::path file = kSource / "framework/scenario/test/bad/yaml_syntax.yaml";
  EXPECT_EQ(Validate(file, cwd).err, "fitfeel: error: " + file.string() +
                                         ":10:9: expected valid YAML, found end of map flow "
                                         "not found\n");
}

TEST(ValidateCommandTest, MissingFileExitsTwo) {
  if (!fs::exists(kFitfeel)) GTEST_SKIP() << "build the fitfeel target first: " << kFitfeel;
  const fs::path cwd = EmptyFolder("missing");
  const Result result = Validate(cwd / "nope.yaml", cwd);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("expected a readable scenario file"));
  EXPECT_TRUE(fs::is_empty(cwd));
}

}  // namespace
