#pragma once

// Running the built fitfeel CLI from a test as a user would, through the shell, and capturing
// what it printed and how it exited. Header-only; for test binaries made by fitfeel_add_test,
// which defines FITFEEL_TEST_BUILD_DIR.
//
//   using fitfeel::test_support::RunFitfeel;
//   const CliResult r = RunFitfeel("validate " + ShellQuote(file), CliOptions().In(dir));
//   EXPECT_EQ(r.exit_code, 2) << r.err;

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/testing/source_tree.h"

#ifndef FITFEEL_TEST_BUILD_DIR
#error "cli_runner.h is for test binaries made by fitfeel_add_test (FITFEEL_TEST_BUILD_DIR)"
#endif

// Not fitfeel::testing: inside namespace fitfeel that name would hide GoogleTest's ::testing.
namespace fitfeel::test_support {

struct CliResult {
  int exit_code = -1;  // -1: the CLI did not exit by itself (a signal), or no shell ran
  std::string out;     // standard output (with standard error, when merged)
  std::string err;     // standard error (empty when merged)
};

// How to run it, built in a chain: CliOptions().In(dir).WithPluginPath(path).
struct CliOptions {
  // Where the CLI runs; empty: the test's own working folder (ctest runs tests in the repository).
  std::filesystem::path cwd;
  // FITFEEL_PLUGIN_PATH for the run; empty: the test's own environment.
  std::string plugin_path;
  // Standard error into `out`, interleaved as written, for checks that do not care which stream.
  bool merge_stderr = false;

  CliOptions& In(const std::filesystem::path& folder) {
    cwd = folder;
    return *this;
  }
  CliOptions& WithPluginPath(const std::string& path) {
    plugin_path = path;
    return *this;
  }
  CliOptions& MergingStderr() {
    merge_stderr = true;
    return *this;
  }
};

// The CLI this build made.
inline std::filesystem::path FitfeelBinary() {
  return std::filesystem::path(FITFEEL_TEST_BUILD_DIR) / "bin" / "fitfeel";
}

// `word` as one shell word, whatever it holds.
inline std::string ShellQuote(const std::string& word) {
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Every word quoted, joined by spaces.
inline std::string ShellWords(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + ShellQuote(word);
  return line;
}

// The whole of `file`; empty if it cannot be read.
inline std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Writes `text` to `file` (a scenario a test edits), replacing what was there.
inline void WriteText(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
}

// The lines of a text, without their line breaks.
inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The cells of one CSV line (no quoting: fitfeel's CSV cells hold none).
inline std::vector<std::string> SplitCells(const std::string& line, char separator = ',') {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, separator);) out.push_back(cell);
  return out;
}

// An empty folder <test temp dir>/<group>/<name>, emptied if a previous run left it.
inline std::filesystem::path EmptyFolder(const std::string& group, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / group / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// An empty folder <test temp dir>/<group>/<running test's name>. The temporary folder is the
// process's own (framework/testing/test_main.cc), so no process number is needed in the name.
inline std::filesystem::path EmptyTestFolder(const std::string& group) {
  return EmptyFolder(group, ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

namespace internal {

// A capture file of its own for each run of each test process, outside the folder the CLI runs
// in (tests check that folder for what the CLI wrote).
inline std::filesystem::path CaptureFile(const char* stream) {
  static std::atomic<int> runs{0};
  return std::filesystem::temp_directory_path() / ("fitfeel-cli-" + std::to_string(::getpid()) +
                                                   "-" + std::to_string(runs++) + "." + stream);
}

}  // namespace internal

// Runs `fitfeel <arguments>`, where `arguments` is shell text: the caller quotes words that need
// it (ShellQuote, ShellWords).
inline CliResult RunFitfeel(const std::string& arguments, const CliOptions& options = {}) {
  const std::filesystem::path out = internal::CaptureFile("out");
  const std::filesystem::path err = internal::CaptureFile("err");
  std::string command;
  if (!options.cwd.empty()) command += "cd " + ShellQuote(options.cwd.string()) + " && ";
  if (!options.plugin_path.empty()) {
    command += "FITFEEL_PLUGIN_PATH=" + ShellQuote(options.plugin_path) + " ";
  }
  command += ShellQuote(FitfeelBinary().string()) + " " + arguments + " >" +
             ShellQuote(out.string()) +
             (options.merge_stderr ? std::string(" 2>&1") : " 2>" + ShellQuote(err.string()));
  const int status = std::system(command.c_str());
  CliResult result;
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = ReadText(out);
  result.err = ReadText(err);
  std::error_code ignored;
  std::filesystem::remove(out, ignored);
  std::filesystem::remove(err, ignored);
  return result;
}

// Runs `fitfeel <arguments>` from the repository's root (where scenarios name their files),
// stdout and stderr together.
inline CliResult RunFitfeelInSourceTree(const std::string& arguments) {
  return RunFitfeel(arguments, CliOptions().In(kSourceTree).MergingStderr());
}

}  // namespace fitfeel::test_support
