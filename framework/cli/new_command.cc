// `fitfeel new KIND [FILE]`: a commented starting scenario of a chosen kind, taken from the shipped
// scenario of that kind (whose comments say where every value comes from), renamed after FILE and
// checked to load before it is written.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/core/atomic_files.h"
#include "framework/core/error.h"
#include "framework/core/path_check.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

struct Kind {
  const char* name;
  const char* scenario;  // the shipped one it starts from
  const char* what;
};

constexpr Kind kKinds[] = {
    {"clearance-fit", "paper-case1-h7g6.yaml", "a shaft into a bushing, H7/g6, pushed by a robot"},
    {"transition-fit", "paper-case1-h7js6.yaml", "the paper's case study, H7/js6"},
    {"press-fit", "fits-20mm-h7s6.yaml", "an H7/s6 press fit, pressed by a robot"},
    {"by-hand", "hand-h7g6.yaml", "a person's hand inserting an H7/g6 shaft"},
    {"tilted", "tilted-start-h7g6.yaml", "a shaft started crooked: two-point contact"},
    {"taper-pin", "taper-pin.yaml", "a taper pin pressed into its reamed hole"},
    {"key", "key-parallel.yaml", "a parallel key into its keyway"},
    {"keyed-hub", "keyed-hub.yaml", "a hub onto a shaft and key at once (two features)"},
    {"two-pins", "two-pin-location.yaml", "a plate onto two locating pins"},
    {"bearing", "knuckle-bearing.yaml", "a spherical plain bearing turned in its housing"},
    {"bolt", "bolt-m10.yaml", "a nut run down an M10 bolt and tightened"},
};

std::string KindList() {
  std::string out;
  for (const Kind& k : kKinds) out += std::string(out.empty() ? "" : ", ") + k.name;
  return out;
}

const Kind& FindKind(const std::string& name) {
  for (const Kind& k : kKinds) {
    if (name == k.name) return k;
  }
  throw UserError("new: unknown kind '" + name + "'; the kinds are " + KindList() +
                  " (fitfeel new --list)");
}

// The shipped scenario's text with its `scenario:` name replaced by `name`.
std::string Renamed(const std::string& text, const std::string& name, const fs::path& from) {
  std::istringstream in(text);
  std::ostringstream out;
  std::string line;
  bool renamed = false;
  while (std::getline(in, line)) {
    if (!renamed && line.rfind("scenario:", 0) == 0) {
      line = "scenario: " + name;
      renamed = true;
    }
    out << line << "\n";
  }
  if (!renamed) throw UserError("new: '" + from.string() + "' has no top-level scenario: key");
  return out.str();
}

struct NewArgs {
  std::string kind;
  std::string file;
  bool list = false;
  bool force = false;
};

void RunNew(const NewArgs& args) {
  if (args.list || args.kind.empty()) {
    for (const Kind& k : kKinds) std::cout << "  " << k.name << ": " << k.what << "\n";
    if (!args.list) throw UserError("new: give a kind (" + KindList() + ")");
    return;
  }
  const Kind& kind = FindKind(args.kind);
  const fs::path shipped = FindShippedFile(fs::path("scenarios") / kind.scenario);
  if (shipped.empty()) {
    throw UserError(std::string("new: the shipped scenario '") + kind.scenario +
                    "' was not found (an install without its share/fitfeel/scenarios?)");
  }
  const fs::path file = args.file.empty() ? fs::path(args.kind + ".yaml") : fs::path(args.file);
  if (file.filename().empty() || file.extension() != ".yaml") {
    throw UserError("new: the output must be a .yaml file, found '" + file.string() + "'");
  }
  if (!args.force && WhyNotReadableFile(file) != kDoesNotExist) {
    throw UserError("new: '" + file.string() + "' exists; give another name or --force");
  }
  std::ifstream in(shipped);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw UserError("new: cannot read '" + shipped.string() + "'");
  const std::string header = "# Started with `fitfeel new " + args.kind + "` from the shipped " +
                             kind.scenario + ": " + kind.what +
                             ".\n# Every value says where it comes from; run it with `fitfeel "
                             "run " +
                             file.filename().string() + "`.\n";
  const std::string content = header + Renamed(text.str(), file.stem().string(), shipped);
  // What is written loads: the same parse and checks as `fitfeel validate`.
  PluginRegistry registry;
  registry.LoadAll();
  LoadSceneFromYaml(content, file, registry);
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  WriteFilesAtomically(dir, {{file.filename().string(), content}});
  std::cout << "wrote " << file.string() << " (" << kind.what << ")\n";
}

}  // namespace

void AddNewCommand(CLI::App& app) {
  auto args = std::make_shared<NewArgs>();
  auto* cmd = app.add_subcommand(
      "new", "Write a commented starting scenario of a chosen kind (fitfeel new --list)");
  cmd->add_option("kind", args->kind, "what to start from: " + KindList());
  cmd->add_option("file", args->file, "scenario file to write (default: KIND.yaml)");
  cmd->add_flag("--list", args->list, "list the kinds and exit");
  cmd->add_flag("--force", args->force, "replace FILE if it exists");
  cmd->callback([args] { RunNew(*args); });
}

}  // namespace fitfeel::cli
