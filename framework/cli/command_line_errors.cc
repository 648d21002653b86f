#include "framework/cli/command_line_errors.h"

#include <cctype>
#include <optional>
#include <regex>
#include <vector>

namespace fitfeel::cli {
// A namespace of its own: the CLI is built in unity batches, where anonymous namespaces merge.
namespace command_line_errors {
namespace {

// CLI11 marks an option without an upper bound on its values by this many.
constexpr int kUnbounded = 1 << 20;

std::string Quoted(const std::string& word) { return word.empty() ? "nothing" : "'" + word + "'"; }

std::string Join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

std::string LowerFirst(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

// How an argument is named to the user: "<file>" (or the text it shows, "<size> <HOLE/shaft>") for
// a positional, "--output" for an option.
std::string Shown(const CLI::Option& option) {
  if (option.get_positional() && !option.nonpositional()) {
    return option.get_option_text().empty() ? "<" + option.get_name() + ">"
                                            : option.get_option_text();
  }
  return option.get_name();
}

// The option a CLI11 message names (a positional's name or "--out"), when the command has it.
const CLI::Option* Find(const CLI::App& command, const std::string& name) {
  return name.empty() ? nullptr : command.get_option_no_throw(name);
}

std::string ShownName(const CLI::App& command, const std::string& name) {
  const CLI::Option* option = Find(command, name);
  return option != nullptr ? Shown(*option) : name;
}

std::string CountOf(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// "2 or 3 words", "exactly 1 value", "at least 1 value".
std::string ExpectedCount(const CLI::Option* option) {
  if (option == nullptr) return "another number of values";
  const int low = option->get_items_expected_min();
  const int high = option->get_items_expected_max();
  const bool positional = option->get_positional() && !option->nonpositional();
  const char* one = positional ? "word" : "value";
  const char* many = positional ? "words" : "values";
  if (high >= kUnbounded) return "at least " + CountOf(low, one, many);
  if (low == high) return "exactly " + CountOf(low, one, many);
  if (high == low + 1) return std::to_string(low) + " or " + CountOf(high, one, many);
  return std::to_string(low) + " to " + CountOf(high, one, many);
}

// "a whole number" for CLI11's type names (typed options: view's --port, --frame-rate).
std::string ExpectedType(const CLI::Option* option) {
  const std::string type = option != nullptr ? option->get_type_name() : "";
  if (StartsWith(type, "UINT")) return "a whole number, 0 or more";
  if (StartsWith(type, "INT")) return "a whole number";
  if (StartsWith(type, "FLOAT")) return "a number";
  if (StartsWith(type, "BOOLEAN")) return "true or false";
  return "a value of another form";
}

std::optional<std::smatch> Match(const std::string& text, const char* pattern) {
  std::smatch match;
  if (!std::regex_match(text, match, std::regex(pattern))) return std::nullopt;
  return match;
}

// The words CLI11 left over (unknown options, surplus positionals), in command-line order.
std::vector<std::string> LeftOver(const CLI::App& app, const std::string& message) {
  std::vector<std::string> words = app.remaining(true);
  if (!words.empty()) return words;
  const std::size_t colon = message.find(": ");
  if (colon == std::string::npos) return words;
  std::string rest = message.substr(colon + 2);
  for (std::size_t start = 0; start <= rest.size();) {
    const std::size_t end = std::min(rest.find(' ', start), rest.size());
    if (end > start) words.push_back(rest.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

std::string SubcommandNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* sub : command.get_subcommands(std::function<bool(const CLI::App*)>{})) {
    names.push_back(sub->get_name());
  }
  return Join(names, ", ");
}

// What was expected and what was found, in the project's words, for each kind of CLI11 refusal.
std::string Explain(const CLI::ParseError& error, const CLI::App& app, const CLI::App& command) {
  // By type: an error's name is not always its kind (ExtrasError takes the command's name).
  const auto is = [&error](const auto* kind) {
    return dynamic_cast<decltype(kind)>(&error) != nullptr;
  };
  const std::string message = error.what();
  if (is(static_cast<const CLI::RequiredError*>(nullptr))) {
    if (StartsWith(message, "A subcommand") || StartsWith(message, "Requires at least")) {
      const std::vector<std::string> words = command.remaining(false);
      return "expected a command (" + SubcommandNames(command) + "), found " +
             (words.empty() ? "none" : Quoted(words.front()));
    }
    if (const auto m = Match(message, "(.+) is required")) {
      const CLI::Option* option = Find(command, (*m)[1]);
      std::string missing = "missing " + ShownName(command, (*m)[1]);
      if (option != nullptr && !option->get_description().empty()) {
        missing += " (" + LowerFirst(option->get_description()) + ")";
      }
      return missing;
    }
  } else if (is(static_cast<const CLI::ArgumentMismatch*>(nullptr))) {
    if (const auto m = Match(message, "(\\S+): \\d+ required \\S+ missing")) {
      return ShownName(command, (*m)[1]) + ": expected a value, found none";
    }
    if (const auto m = Match(message, "(\\S+): At (?:least|Most) \\d+ required but received (\\d+)")) {
      return ShownName(command, (*m)[1]) + ": expected " + ExpectedCount(Find(command, (*m)[1])) +
             ", found " + std::string((*m)[2]);
    }
    if (const auto m = Match(message, "Expected (?:exactly|at least) \\d+ arguments to (\\S+), got (\\d+)")) {
      return ShownName(command, (*m)[1]) + ": expected " + ExpectedCount(Find(command, (*m)[1])) +
             ", found " + std::string((*m)[2]);
    }
    if (const auto m = Match(message, "(\\S+) was given a disallowed flag override")) {
      return ShownName(command, (*m)[1]) + ": expected no value (a flag), found one";
    }
  } else if (is(static_cast<const CLI::ExtrasError*>(nullptr))) {
    const std::vector<std::string> words = LeftOver(app, message);
    std::vector<std::string> options, arguments;
    for (const std::string& word : words) {
      (StartsWith(word, "-") && word.size() > 1 ? options : arguments).push_back(Quoted(word));
    }
    std::vector<std::string> parts;
    if (!options.empty()) {
      parts.push_back((options.size() == 1 ? "unknown option " : "unknown options ") +
                      Join(options, ", "));
    }
    if (!arguments.empty()) {
      parts.push_back((arguments.size() == 1 ? "unexpected argument " : "unexpected arguments ") +
                      Join(arguments, ", "));
    }
    if (!parts.empty()) return Join(parts, "; ");
  } else if (is(static_cast<const CLI::ExcludesError*>(nullptr))) {
    if (const auto m = Match(message, "(\\S+) excludes (\\S+)")) {
      return "expected one of " + std::string((*m)[1]) + " and " + std::string((*m)[2]) +
             ", found both";
    }
  } else if (is(static_cast<const CLI::RequiresError*>(nullptr))) {
    if (const auto m = Match(message, "(\\S+) requires (\\S+)")) {
      return std::string((*m)[1]) + ": expected " + std::string((*m)[2]) + " as well, found none";
    }
  } else if (is(static_cast<const CLI::ValidationError*>(nullptr))) {
    if (const auto m = Match(message, "(\\S+): (.*) not in \\{(.*)\\}")) {
      std::string choices = (*m)[3];
      for (std::size_t comma = choices.find(','); comma != std::string::npos;
           comma = choices.find(',', comma + 2)) {
        choices.replace(comma, 1, ", ");
      }
      return ShownName(command, (*m)[1]) + ": expected one of " + choices + ", found " +
             Quoted((*m)[2]);
    }
  } else if (is(static_cast<const CLI::ConversionError*>(nullptr))) {
    if (const auto m = Match(message, "Could not convert: (\\S+) = (.*)")) {
      return ShownName(command, (*m)[1]) + ": expected " + ExpectedType(Find(command, (*m)[1])) +
             ", found " + Quoted((*m)[2]);
    }
    if (const auto m = Match(message, "The value (.*) is not an allowed value for (\\S+)")) {
      return ShownName(command, (*m)[2]) + ": expected " + ExpectedType(Find(command, (*m)[2])) +
             ", found " + Quoted((*m)[1]);
    }
    if (const auto m = Match(message, "(\\S+): too many inputs for a flag")) {
      return ShownName(command, (*m)[1]) + ": expected no value (a flag), found more than one";
    }
    if (const auto m = Match(message, "(\\S+): Should be true/false or a number")) {
      return ShownName(command, (*m)[1]) + ": expected true, false or a number, found another value";
    }
  }
  // A refusal of a kind this command line cannot produce today: say so in the project's words
  // rather than pass CLI11's on.
  return "the arguments do not fit the command";
}

std::string Prefixed(const CLI::App& command, const std::string& what) {
  const std::string path = CommandPath(command);
  const std::string name = path.size() > 8 ? path.substr(8) + ": " : "";  // after "fitfeel "
  return "fitfeel: error: " + name + what + "\n" + UsageLine(command);
}

}  // namespace
}  // namespace command_line_errors

using command_line_errors::Explain;
using command_line_errors::Join;
using command_line_errors::Prefixed;
using command_line_errors::Shown;

const CLI::App& GivenCommand(const CLI::App& app) {
  const CLI::App* command = &app;
  for (;;) {
    const std::vector<CLI::App*> given = command->get_subcommands();
    if (given.empty()) return *command;
    command = given.front();
  }
}

std::string CommandPath(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* a = &command; a->get_parent() != nullptr; a = a->get_parent()) {
    names.insert(names.begin(), a->get_name());
  }
  names.insert(names.begin(), "fitfeel");
  return Join(names, " ");
}

std::string UsageLine(const CLI::App& command) {
  const std::string path = CommandPath(command);
  std::vector<std::string> words = {path};
  const std::vector<const CLI::App*> subcommands =
      command.get_subcommands(std::function<bool(const CLI::App*)>{});
  if (!subcommands.empty()) {
    std::vector<std::string> names;
    for (const CLI::App* sub : subcommands) names.push_back(sub->get_name());
    words.push_back(Join(names, "|"));
    words.push_back("...");
  }
  const auto options = command.get_options();
  for (const CLI::Option* option : options) {
    if (!option->get_positional() || option->nonpositional()) continue;
    std::string word = Shown(*option);
    if (option->get_items_expected_max() > 1 && option->get_option_text().empty()) word += "...";
    words.push_back(option->get_required() ? word : "[" + word + "]");
  }
  for (const CLI::Option* option : options) {
    if (!option->nonpositional() || !option->get_required()) continue;
    std::string value = option->get_name();
    while (!value.empty() && value.front() == '-') value.erase(0, 1);
    words.push_back(option->get_name() + " <" + value + ">");
  }
  words.push_back("[options]");
  return "usage: " + Join(words, " ") + " (more: " + path + " --help)";
}

std::string DescribeParseError(const CLI::ParseError& error, const CLI::App& app) {
  const CLI::App& command = GivenCommand(app);
  return Prefixed(command, Explain(error, app, command));
}

std::string DescribeOptionError(const std::string& what, const CLI::App& app) {
  return Prefixed(GivenCommand(app), what);
}

}  // namespace fitfeel::cli
