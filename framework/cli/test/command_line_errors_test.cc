// Every command-line error in the project's format: "fitfeel: error: <command>: <what was
// expected, what was found>", then the command's usage line; exit code 2; never the argument
// library's own words.
#include "framework/cli/command_line_errors.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel::cli {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// CLI11's phrasing: none of it may reach the user.
const std::vector<std::string> kLibraryWords = {
    "At least",         "At Most",         "required but received", "The following argument",
    "Run with --help",  "is required",     "Could not convert",     "not in {",
    "Expected exactly", "required TEXT",   " excludes ",            " requires ",
    "A subcommand",     "Should be true",  "not expected"};

struct BadLine {
  std::vector<std::string> words;  // after `fitfeel`
  std::string command;             // "plot trace", "" for fitfeel itself
  std::string what;                // the first line after "fitfeel: error: "
};

// An empty folder of this process and test to run the CLI in (it must write nothing there).
std::filesystem::path TestFolder() { return test_support::EmptyTestFolder("command-line"); }

std::string Describe(const BadLine& line) {
  return "fitfeel " + test_support::ShellWords(line.words);
}

// At least one of each kind of refusal, and one for each command.
const std::vector<BadLine> kBadLines = {
    // A command missing, unknown.
    {{}, "", "expected a command (run, validate, plugins, fit, sms, plot, stability, tradeoff, "
             "study, view, new, import), found none"},
    {{"bogus"}, "", "expected a command (run, validate, plugins, fit, sms, plot, stability, "
                    "tradeoff, study, view, new, import), found 'bogus'"},
    {{"--bogus"}, "", "expected a command (run, validate, plugins, fit, sms, plot, stability, "
                      "tradeoff, study, view, new, import), found '--bogus'"},
    {{"plot"}, "plot", "expected a command (trace, sms, pressure, study, mapping), found none"},
    {{"plot", "bogus"}, "plot",
     "expected a command (trace, sms, pressure, study, mapping), found 'bogus'"},
    // An argument or a required option missing.
    {{"validate"}, "validate", "missing <file> (scenario file (YAML))"},
    {{"fit"}, "fit", "missing <size> <HOLE/shaft> (e.g. 20 H7/g6 or \"20 mm\" H7/js6)"},
    {{"sms"}, "sms", "missing <file> (scenario file (YAML))"},
    {{"tradeoff"}, "tradeoff", "missing <scenario> (scenario file)"},
    {{"study"}, "study", "missing <file> (scenario file)"},
    {{"plot", "trace"}, "plot trace", "missing <DIR> (run folders holding trace.csv and summary.json)"},
    {{"plot", "trace", "run"}, "plot trace",
     "missing --output (image file: .png, .svg, or no extension for both)"},
    {{"plot", "sms"}, "plot sms", "missing <SCENARIO> (scenario file (YAML))"},
    {{"plot", "pressure", "run", "-o", "p.png"}, "plot pressure",
     "missing --depth (insertion depth in mm, inside the run's constrained range)"},
    {{"plot", "study"}, "plot study",
     "missing <DIR> (study folders holding pairs.csv and study.json)"},
    // The wrong number of values.
    {{"fit", "20"}, "fit", "<size> <HOLE/shaft>: expected 2 or 3 words, found 1"},
    {{"fit", "20", "mm", "H7/g6", "x"}, "fit", "<size> <HOLE/shaft>: expected 2 or 3 words, found 4"},
    {{"run", "--seed"}, "run", "--seed: expected a value, found none"},
    {{"sms", "s.yaml", "--part"}, "sms", "--part: expected a value, found none"},
    {{"stability", "--rate"}, "stability", "--rate: expected a value, found none"},
    // Words left over: unknown options, surplus arguments.
    {{"run", "a.yaml", "b.yaml"}, "run", "unexpected argument 'b.yaml'"},
    {{"run", "--bogus"}, "run", "unknown option '--bogus'"},
    {{"validate", "a.yaml", "b.yaml"}, "validate", "unexpected argument 'b.yaml'"},
    {{"plugins", "extra"}, "plugins", "unexpected argument 'extra'"},
    {{"plugins", "--seed", "1"}, "plugins", "unknown option '--seed'; unexpected argument '1'"},
    {{"fit", "--x", "20", "H7/g6"}, "fit", "unknown option '--x'"},
    {{"stability", "a.yaml", "b.yaml"}, "stability", "unexpected argument 'b.yaml'"},
    {{"view", "a.yaml", "b.yaml"}, "view", "unexpected argument 'b.yaml'"},
    // Options that exclude each other.
    {{"run", "--realtime", "--virtual"}, "run", "expected one of --realtime and --virtual, found both"},
    {{"view", "--realtime", "--virtual"}, "view", "expected one of --realtime and --virtual, found both"},
    // A value outside its choices, of the wrong type.
    {{"tradeoff", "s.yaml", "--cost", "p90"}, "tradeoff", "--cost: expected one of p50, p99, found 'p90'"},
    {{"view", "--port", "abc"}, "view", "--port: expected a whole number, 0 or more, found 'abc'"},
    {{"view", "--frame-rate", "x"}, "view", "--frame-rate: expected a number, found 'x'"},
    // The project's own strict options.
    {{"run", "--seed", "-1"}, "run", "--seed: expected an integer in [0, 18446744073709551615], found '-1'"},
    {{"study", "s.yaml", "--pairs", "0"}, "study", "--pairs: expected an integer in [1, 10000000], found '0'"},
    {{"tradeoff", "s.yaml", "--seeds", "0"}, "tradeoff", "--seeds: expected an integer in [1, 1000], found '0'"},
    {{"stability", "--per-decade", "0"}, "stability", "--per-decade: expected an integer in [1, 100], found '0'"},
    {{"plot", "sms", "s.yaml", "--seed", "x", "-o", "p.png"}, "plot sms",
     "--seed: expected an integer in [0, 18446744073709551615], found 'x'"},
    // A control character is shown, not sent to the terminal.
    {{"run", "--seed", "\x1b[31m"}, "run",
     "--seed: expected an integer in [0, 18446744073709551615], found '\\x1b[31m'"},
};

TEST(CommandLineErrorsTest, EveryBadCommandLineAnswersInTheProjectsFormatWithItsUsage) {
  const std::filesystem::path dir = TestFolder();
  for (const BadLine& line : kBadLines) {
    const test_support::CliResult r = test_support::RunFitfeel(
        test_support::ShellWords(line.words), test_support::CliOptions().In(dir));
    EXPECT_EQ(r.exit_code, 2) << Describe(line) << "\n" << r.err;
    EXPECT_EQ(r.out, "") << Describe(line);
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << Describe(line) << " wrote into its folder";
    const std::vector<std::string> lines = test_support::Lines(r.err);
    ASSERT_EQ(lines.size(), 2u) << Describe(line) << "\n" << r.err;
    const std::string path = line.command.empty() ? "fitfeel" : "fitfeel " + line.command;
    // The error names the command as the user typed it ("plot trace: ").
    const std::string named = line.command.empty() ? "" : line.command + ": ";
    EXPECT_EQ(lines[0], "fitfeel: error: " + named + line.what) << Describe(line);
    EXPECT_THAT(lines[1], StartsWith("usage: " + path + " ")) << Describe(line);
    EXPECT_THAT(lines[1], ::testing::EndsWith("(more: " + path + " --help)")) << Describe(line);
    for (const std::string& words : kLibraryWords) {
      EXPECT_THAT(r.err, ::testing::Not(HasSubstr(words))) << Describe(line);
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(CommandLineErrorsTest, UsageLinesFollowTheCommandsDefinitions) {
  const std::filesystem::path dir = TestFolder();
  const std::vector<std::pair<std::vector<std::string>, std::string>> usages = {
      {{"run", "--bogus"}, "usage: fitfeel run [<file>] [options] (more: fitfeel run --help)"},
      {{"fit", "20"},
       "usage: fitfeel fit <size> <HOLE/shaft> [options] (more: fitfeel fit --help)"},
      {{"plot", "pressure", "run"},
       "usage: fitfeel plot pressure <DIR> --depth <depth> --output <output> [options] (more: "
       "fitfeel plot pressure --help)"},
      {{"plot", "trace"},
       "usage: fitfeel plot trace <DIR>... --output <output> [options] (more: fitfeel plot trace "
       "--help)"},
      {{"plot"},
       "usage: fitfeel plot trace|sms|pressure|study|mapping ... [options] (more: fitfeel plot "
       "--help)"},
  };
  for (const auto& [words, usage] : usages) {
    const test_support::CliResult r =
        test_support::RunFitfeel(test_support::ShellWords(words), test_support::CliOptions().In(dir));
    const std::vector<std::string> lines = test_support::Lines(r.err);
    ASSERT_EQ(lines.size(), 2u) << r.err;
    EXPECT_EQ(lines[1], usage);
  }
  std::filesystem::remove_all(dir);
}

TEST(CommandLineErrorsTest, HelpAndVersionStillSucceed) {
  for (const char* words : {"--help", "run --help", "plot trace --help", "--version"}) {
    const test_support::CliResult r = test_support::RunFitfeel(words);
    EXPECT_EQ(r.exit_code, 0) << words << "\n" << r.err;
    EXPECT_EQ(r.err, "") << words;
    EXPECT_NE(r.out, "") << words;
  }
}

TEST(CommandLineErrorsTest, AControlCharacterFromAFileNeitherBreaksTheLineNorReachesTheTerminal) {
  const std::filesystem::path dir = TestFolder();
  const std::filesystem::path scenario = dir / "key.yaml";
  std::ofstream(scenario) << "scenario: s\nsur\fface: x\n";
  const test_support::CliResult r = test_support::RunFitfeel(
      test_support::ShellWords({"validate", scenario.string()}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const std::vector<std::string> lines = test_support::Lines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_THAT(lines[0], StartsWith("fitfeel: error: " + scenario.string() + ":"));
  EXPECT_THAT(lines[0], HasSubstr("sur\\x0cface"));
  EXPECT_EQ(r.err.find('\f'), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Kinds no fitfeel command line produces today, through an application of their own.
std::string Refusal(CLI::App& app, std::vector<std::string> words) {
  words.insert(words.begin(), "fitfeel");
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    return DescribeParseError(e, app);
  }
  return "parsed";
}

TEST(CommandLineErrorsTest, AnOptionThatNeedsAnotherSaysWhich) {
  CLI::App app;
  CLI::App* cmd = app.add_subcommand("cmd", "");
  std::string a, b;
  CLI::Option* b_option = cmd->add_option("--b", b, "");
  cmd->add_option("--a", a, "")->needs(b_option);
  EXPECT_EQ(Refusal(app, {"cmd", "--a", "1"}),
            "fitfeel: error: cmd: --a: expected --b as well, found none\n"
            "usage: fitfeel cmd [options] (more: fitfeel cmd --help)");
}

TEST(CommandLineErrorsTest, AFlagGivenAValueItCannotTakeIsRefusedInTheProjectsWords) {
  CLI::App app;
  bool flag = false;
  app.add_flag("--flag", flag, "");
  const std::string refusal = Refusal(app, {"--flag=maybe"});
  EXPECT_THAT(refusal, StartsWith("fitfeel: error: --flag: expected "));
  for (const std::string& words : kLibraryWords) EXPECT_THAT(refusal, ::testing::Not(HasSubstr(words)));
}

TEST(CommandLineErrorsTest, AKindNotForeseenStillAnswersInTheProjectsWords) {
  CLI::App app;
  EXPECT_EQ(DescribeParseError(CLI::HorribleError("the library's own words"), app),
            "fitfeel: error: the arguments do not fit the command\n"
            "usage: fitfeel [options] (more: fitfeel --help)");
}

}  // namespace
}  // namespace fitfeel::cli
