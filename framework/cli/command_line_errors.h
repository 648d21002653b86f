#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace fitfeel::cli {

// Command-line errors in the project's format. CLI11 words its refusals its own way ("size_and_fit:
// At least 2 required but received 1", "Run with --help for more information."); main catches
// every CLI::ParseError in one place and prints this instead, exit code 2:
//
//   fitfeel: error: fit: <size> <HOLE/shaft>: expected 2 or 3 words, found 1
//   usage: fitfeel fit <size> <HOLE/shaft> [options] (more: fitfeel fit --help)

// The command the user named: `app` itself or its deepest subcommand given ("plot trace").
const CLI::App& GivenCommand(const CLI::App& app);

// "fitfeel", "fitfeel run", "fitfeel plot trace".
std::string CommandPath(const CLI::App& command);

// "usage: fitfeel run [<file>] [options] (more: fitfeel run --help)": positionals in order
// (optional ones in brackets, repeatable ones with "..."), then the required options, from the
// command's own definition, so that it never falls out of step with it.
std::string UsageLine(const CLI::App& command);

// The two lines main prints (no trailing newline) for a refusal of CLI11's: "fitfeel: error: ",
// the command ("run: "), what was expected and found, and the usage line. `app` is the parsed
// application (its state says which command and which words were left over).
std::string DescribeParseError(const CLI::ParseError& error, const CLI::App& app);

// The same two lines for an error the command line caused elsewhere (a strict option's
// OptionError): "fitfeel: error: run: --seed: expected ..., found '-1'" and the usage line.
std::string DescribeOptionError(const std::string& what, const CLI::App& app);

}  // namespace fitfeel::cli
