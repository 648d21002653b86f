#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/cli/interrupts.h"
#include "framework/cli/strict_options.h"
#include "framework/runtime/prepare.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/os_reason.h"
#include "framework/core/path_check.h"
#include "framework/core/temporary_files.h"
#include "framework/model/measured_surface.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"

namespace fitfeel::cli {
namespace {

std::string Micrometres(double metres) {
  char buffer[64];
  // Below half the last digit shown is zero, printed without a sign ("-0.000" misleads).
  if (std::abs(metres) < 5e-10) return "0.000 um";
  std::snprintf(buffer, sizeof buffer, "%+.3f um", metres * 1e6);
  return buffer;
}

// Writes `text` to `path` atomically: a temporary file in the same folder, flushed, then renamed
// over the target, so a reader never sees half a file and a failure leaves the old file alone.
void WriteAtomically(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path folder =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (const std::string why = WhyNotFolder(folder); !why.empty()) {
    throw UserError("sms: cannot write '" + path.string() + "': folder '" + folder.string() +
                    "' " + why);
  }
  const std::filesystem::path temporary = TemporaryPathFor(path);
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    const int write_error = errno;
    if (!out) {
      std::filesystem::remove(temporary, ec);
      throw UserError("sms: cannot write '" + temporary.string() + "': " + OsReason(write_error));
    }
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw UserError("sms: cannot replace '" + path.string() + "': " + ec.message());
  }
}

std::string Csv(const SkinModelShape& sms) {
  const SurfaceGrid& g = sms.grid;
  std::ostringstream out;
  out.precision(10);
  out << "row,column,axial_mm,angle_deg,x_mm,y_mm,z_mm,area_mm2,v_um,v_dimension_um,v_form_um,"
         "v_surface_um\n";
  auto part = [](const Eigen::VectorXd& v, int c) { return v.size() > c ? v(c) * 1e6 : 0.0; };
  for (int i = 0; i < g.rows; ++i) {
    for (int j = 0; j < g.columns; ++j) {
      const int c = g.index(i, j);
      out << i << ',' << j << ',' << g.row_position(i) * 1e3 << ','
          << g.column_angle(j) * 180.0 / std::numbers::pi << ',' << g.centre(0, c) * 1e3 << ','
          << g.centre(1, c) * 1e3 << ',' << g.centre(2, c) * 1e3 << ',' << g.area(c) * 1e6 << ','
          << sms.variation(c) * 1e6 << ',' << part(sms.dimension_part, c) << ','
          << part(sms.form_part, c) << ',' << part(sms.surface_part, c) << '\n';
    }
  }
  return out.str();
}

struct SmsOptions {
  std::string file;
  std::string part;
  std::string output;
  std::string measurement;
  std::optional<std::uint64_t> seed;
  bool allow_large = false;
};

// The part's characteristics evaluated on its skin model shape against its specification, one
// line each; whether every one passes (a measured part that misses its drawing is a finding about
// the part, not a failure of the generator: it passes here).
bool PrintChecks(const SurfaceType& surface, const PartSpec& p, const SkinModelShape& sms) {
  std::vector<CharacteristicCheck> checks;
  try {
    checks = surface.EvaluateCharacteristics(p, sms);
  } catch (const UnsupportedError& e) {
    // A surface type without a metrology binding still has a shape worth writing.
    std::cout << "  characteristics not evaluated: " << e.what() << "\n";
    return true;
  }
  bool all_pass = true;
  std::printf("  %-22s %14s %30s  %s\n", "characteristic", "evaluated", "spec", "result");
  for (const CharacteristicCheck& check : checks) {
    // Same allowance as the conformance suite: 0.1 nm of evaluation rounding.
    const bool pass = check.value >= check.lower - 1e-10 && check.value <= check.upper + 1e-10;
    if (!p.measured) all_pass = all_pass && pass;
    const std::string spec = "[" + Micrometres(check.lower) + ", " + Micrometres(check.upper) + "]";
    std::printf("  %-22s %14s %30s  %s\n", check.name.c_str(), Micrometres(check.value).c_str(),
                spec.c_str(), pass ? "pass" : "FAIL");
  }
  return all_pass;
}

void Run(const SmsOptions& options) {
  // Until the shapes are drawn nothing is written: SIGINT or SIGTERM ends the process at once;
  // then the writes complete.
  InterruptScope interrupt("fitfeel sms");
  PluginRegistry registry;
  registry.LoadAll();
  for (const RefusedLibrary& refused : registry.refused()) {
    std::cerr << "fitfeel: note: plugin library " << refused.library.string()
              << " was not loaded: " << refused.reason << "\n";
  }
  LoadOptions load;
  load.allow_non_rendering = true;  // skin model shapes exist for surfaces without a law too
  load.allow_large = options.allow_large;
  load.writes_outputs = false;
  const Scene scene = LoadScene(options.file, registry, load);
  const std::vector<const PartSpec*> parts = {&scene.inner, &scene.outer};
  std::vector<const PartSpec*> selected;
  for (const PartSpec* p : parts)
    if (options.part.empty() || p->name == options.part) selected.push_back(p);
  if (selected.empty()) {
    throw UserError("sms: the scene has no part '" + options.part + "' (its parts: '" +
                    scene.inner.name + "', '" + scene.outer.name + "')");
  }
  if (!options.output.empty()) CheckOutputFile("--output", options.output);
  if (!options.measurement.empty()) CheckOutputFile("--measurement", options.measurement);
  if (!options.measurement.empty() && selected.size() != 1) {
    throw UserError("sms: --measurement writes one part; choose it with --part ('" +
                    scene.inner.name + "' or '" + scene.outer.name + "')");
  }
  if (!options.output.empty() && selected.size() != 1) {
    throw UserError("sms: -o writes one part; choose it with --part ('" + scene.inner.name +
                    "' or '" + scene.outer.name + "')");
  }
  const std::uint64_t seed = options.seed.value_or(scene.run.seed);
  // Both parts are generated, inner first, from one generator seeded like a run, so the shapes
  // printed here are the ones `fitfeel run` feels with the same seed.
  Rng rng(seed);
  SkinModelShapes drawn = GenerateSkinModelShapes(scene, rng);
  const std::vector<SkinModelShape> shapes = {std::move(drawn.inner), std::move(drawn.outer)};
  interrupt.Cooperate();
  for (const std::string& file : {options.output, options.measurement}) {
    if (!file.empty()) SweepStaleTemporaries(std::filesystem::path(file).parent_path());
  }
  bool all_pass = true;
  for (size_t k = 0; k < parts.size(); ++k) {
    const PartSpec& p = *parts[k];
    if (std::find(selected.begin(), selected.end(), &p) == selected.end()) continue;
    const SkinModelShape& sms = shapes[k];
    std::cout << "part '" << p.name << "' (" << (p.role == Role::kInner ? "inner" : "outer")
              << "): " << p.geometry->Describe() << "\n"
              << "  grid " << sms.grid.rows << " x " << sms.grid.columns << " = " << sms.grid.size()
              << " cells (" << (scene.model.resolution.is_auto() ? "auto" : "from the scenario")
              << "), seed " << seed << ", texture "
              << TextureModeName(scene.model.texture)
              << ", form regenerations " << sms.regenerations << ", cells scaled back "
              << sms.scaled_back_cells << "\n"
              << "  V from " << Micrometres(sms.variation.minCoeff()) << " to "
              << Micrometres(sms.variation.maxCoeff()) << " (radial)\n";
    if (!options.output.empty()) {
      WriteAtomically(options.output, Csv(sms));
      std::cout << "  wrote " << options.output << "\n";
    }
    if (!options.measurement.empty()) {
      WriteAtomically(options.measurement,
                      MeasurementCsv(sms, "part '" + p.name + "' of " + scene.file.string() +
                                              ", seed " + std::to_string(seed) +
                                              ": the skin model shape as a roundness "
                                              "measurement (one trace per row)"));
      std::cout << "  wrote " << options.measurement << " (roundness measurement)\n";
    }
    if (p.measured) {
      std::cout << "  measured: " << MeasurementKindName(p.measured->kind) << " "
                << p.measured->file.string() << "\n";
    }
    all_pass = PrintChecks(*scene.surface, p, sms) && all_pass;
  }
  // A several-feature scene: every further feature's two parts, drawn after the datum's from the
  // same generator, in the order `fitfeel run` draws them, so that these are the shapes it feels.
  // --part, -o and --measurement address the datum feature's parts.
  if (scene.features.size() > 1 && options.part.empty()) {
    for (std::size_t i = 1; i < scene.features.size(); ++i) {
      const MatingFeature& feature = scene.features[i];
      SkinModelShapes more = GenerateSkinModelShapes(feature, rng);
      const SkinModelShape* feature_shapes[2] = {&more.inner, &more.outer};
      const PartSpec* feature_parts[2] = {&feature.inner, &feature.outer};
      for (int k = 0; k < 2; ++k) {
        const PartSpec& p = *feature_parts[k];
        const SkinModelShape& sms = *feature_shapes[k];
        std::cout << "feature '" << feature.name << "', part '" << p.name << "' ("
                  << (p.role == Role::kInner ? "inner" : "outer")
                  << "): " << p.geometry->Describe() << "\n"
                  << "  grid " << sms.grid.rows << " x " << sms.grid.columns << " = "
                  << sms.grid.size() << " cells, form regenerations " << sms.regenerations
                  << ", cells scaled back " << sms.scaled_back_cells << "\n";
        all_pass = PrintChecks(*feature.surface, p, sms) && all_pass;
      }
    }
  }
  if (!all_pass) {
    // Not a user error: either a generator bug or a model option documented as not promising
    // conformance (the cylindrical plugin's size_draw: per_cell). Exit code 1, after the report.
    throw std::runtime_error(
        "a generated skin model shape does not meet its specification (a generator bug, unless a "
        "model option that does not promise conformance is set: see the surface plugin's README)");
  }
}

}  // namespace

void AddSmsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "sms", "Generate a part's skin model shape, write it as CSV and check it against its spec");
  auto options = std::make_shared<SmsOptions>();
  cmd->add_option("file", options->file, "Scenario file (YAML)")->required();
  cmd->add_option("--part", options->part, "Part name (default: both parts)");
  cmd->add_option("-o,--output", options->output,
                  "CSV file: row, column, axial_mm, angle_deg, x_mm, y_mm, z_mm, area_mm2, v_um, "
                  "v_dimension_um, v_form_um, v_surface_um (needs --part)");
  cmd->add_option("--measurement", options->measurement,
                  "CSV file: the part as a roundness measurement (height, angle, deviation in SI), "
                  "loadable as `measured: {roundness: FILE}` (needs --part)");
  AddSeedOption(
      cmd, "--seed", [options](std::uint64_t s) { options->seed = s; },
      "Seed (default: the scenario's run.seed; the same range)");
  cmd->add_flag("--allow-large", options->allow_large,
                "draw a scene whose estimated preparation exceeds 1 GiB or 30 s");
  cmd->callback([options] { Run(*options); });
}

}  // namespace fitfeel::cli
