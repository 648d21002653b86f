// libFuzzer target: command-line parsing. The input is split at NUL bytes into argv words and
// parsed by a CLI11 app shaped as `fitfeel run` and `fitfeel plot pressure` are (a positional
// file, --out, the strict --seed, a strict quantity, exclusive flags), without running anything.
// Every word list either parses, with the strict options' values in their ranges, or is refused
// with CLI::ParseError or a UserError naming the option; anything else (a crash, another
// exception, a sanitizer report, a value out of range) is a finding. The whole CLI, commands and
// all, is exercised as a process by the campaign (tools/campaign).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "framework/cli/strict_options.h"
#include "framework/core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> words;
  std::string word;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      words.push_back(word);
      word.clear();
    } else {
      word += static_cast<char>(data[i]);
    }
  }
  words.push_back(word);
  if (words.size() > 64) return 0;

  CLI::App app{"fuzz"};
  app.require_subcommand(1);
  CLI::App* run = app.add_subcommand("run", "");
  std::string file, out;
  bool realtime = false, virtual_clock = false, allow_large = false;
  std::uint64_t seed = 0;  // every 64-bit value is a seed: nothing to check once taken
  double depth = std::numeric_limits<double>::quiet_NaN();
  run->add_option("file", file, "");
  run->add_option("--out", out, "");
  fitfeel::cli::AddSeedOption(run, "--seed", [&](std::uint64_t s) { seed = s; }, "");
  fitfeel::cli::AddQuantityOption(
      run, "--depth", fitfeel::Dimension::kLength, -0.01, 0.01, [&](double d) { depth = d; }, "");
  run->add_flag("--allow-large", allow_large, "");
  auto* rt = run->add_flag("--realtime", realtime, "");
  auto* vt = run->add_flag("--virtual", virtual_clock, "");
  rt->excludes(vt);

  // CLI11 takes argv as given, program name first.
  std::vector<std::string> argv_words = {"fitfeel"};
  argv_words.insert(argv_words.end(), words.begin(), words.end());
  std::vector<char*> argv;
  for (std::string& w : argv_words) argv.push_back(w.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    (void)seed;
    if (depth == depth && !(depth >= -0.01 && depth <= 0.01)) std::abort();
    if (realtime && virtual_clock) std::abort();
  } catch (const CLI::ParseError&) {
    // Refused by CLI11 (unknown option, missing value, exclusion): exit code 2 in the CLI.
  } catch (const fitfeel::UserError& e) {
    const std::string what = e.what();
    if (what.rfind("--seed: ", 0) != 0 && what.rfind("--depth: ", 0) != 0) std::abort();
  }
  return 0;
}
