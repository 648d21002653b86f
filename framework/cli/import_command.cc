// `fitfeel import ASSEMBLY.step [--sidecar FILE] [-o SCENARIO.yaml] [--pair N]`: the parts,
// features, tolerances and mating pairs read from a STEP file (and its sidecar), and the scenario
// of the pair, checked to load before it is written (docs/cad-import.md).

#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "framework/cad/import.h"
#include "framework/cad/isolated_read.h"
#include "framework/cli/commands.h"
#include "framework/core/atomic_files.h"
#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"

namespace fitfeel::cli {
namespace {

namespace fs = std::filesystem;

struct ImportArgs {
  std::string file;
  std::string sidecar;
  std::string out;
  int pair = 0;  // 1-based; 0: all pairs
};

// A scenario name (letters, digits, '_', '-', '.') from a file's stem.
std::string ScenarioName(const fs::path& file) {
  std::string name = file.stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '-';
  }
  return name.empty() ? std::string("imported") : name;
}

void RunImport(const ImportArgs& args) {
  // Read before the plugins load: the reader forks, and the process has no threads yet.
  cad::CadDocument document = cad::ReadStep(args.file);
  std::optional<fs::path> sidecar;
  if (!args.sidecar.empty()) sidecar = fs::path(args.sidecar);
  const cad::Import import = cad::BuildImport(std::move(document), sidecar);
  std::cout << cad::DescribeImport(import);
  if (args.out.empty()) return;
  const fs::path out = args.out;
  if (out.filename().empty() || out.extension() != ".yaml") {
    throw UserError("import: the output must be a .yaml file, found '" + out.string() + "'");
  }
  const std::string text =
      cad::ScenarioText(import, ScenarioName(out), fs::path(args.file).filename().string(),
                        args.pair > 0 ? std::optional<std::size_t>(args.pair - 1) : std::nullopt);
  PluginRegistry registry;
  registry.LoadAll();
  LoadSceneFromYaml(text, out, registry);
  const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
  WriteFilesAtomically(dir, {{out.filename().string(), text}});
  std::cout << "wrote " << out.string() << "\n";
}

}  // namespace

void AddImportCommand(CLI::App& app) {
  auto args = std::make_shared<ImportArgs>();
  auto* cmd = app.add_subcommand(
      "import",
      "Read a STEP assembly with its tolerances, list its mating features and write "
      "a scenario of the fit");
  cmd->add_option("file", args->file, "STEP file (AP242 with PMI, AP214, AP203)")->required();
  cmd->add_option("--sidecar", args->sidecar,
                  "YAML file of the tolerances and settings the STEP file lacks");
  cmd->add_option("-o,--out", args->out, "scenario file to write (.yaml)");
  cmd->add_option("--pair", args->pair,
                  "write the scenario of this pair alone (1-based, as listed) where several "
                  "pairs form no joint")
      ->check(CLI::PositiveNumber);
  cmd->callback([args] { RunImport(*args); });
}

}  // namespace fitfeel::cli
