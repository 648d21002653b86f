#include "framework/scenario/scene.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene_summary.h"
#include "framework/scenario/test/fake_plugins.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

const fs::path kTestDir = fs::path(FITFEEL_TEST_SOURCE_DIR) / "framework" / "scenario" / "test";

class SceneTest : public ::testing::Test {
 protected:
  SceneTest() : registry_(std::vector<fs::path>{}) { test::RegisterFakePlugins(registry_); }
  PluginRegistry registry_;
};

// What a refused scenario must say: where, which key, what was expected and what was found.
struct BadCase {
  std::string name;
  int line;
  int column;
  std::string key_path;
  std::string expected;  // substring of ScenarioError::expected()
  std::string found;     // substring of ScenarioError::found()
};

std::ostream& operator<<(std::ostream& out, const BadCase& c) { return out << c.name; }

void ExpectSceneRefused(const fs::path& file, const BadCase& c, const PluginRegistry& registry,
                        const LoadOptions& options = {}) {
  try {
    LoadScene(file, registry, options);
    ADD_FAILURE() << file << " was accepted";
  } catch (const ScenarioError& e) {
    // A whole-file problem has no line: "file: expected ...".
    const std::string prefix =
        file.string() +
        (c.line > 0 ? ":" + std::to_string(c.line) + ":" + std::to_string(c.column) : "") + ": ";
    EXPECT_THAT(std::string(e.what()), StartsWith(prefix)) << e.what();
    EXPECT_EQ(e.where().file, file.string());
    EXPECT_EQ(e.where().line, c.line) << e.what();
    EXPECT_EQ(e.where().column, c.column) << e.what();
    EXPECT_EQ(e.key_path(), c.key_path) << e.what();
    EXPECT_THAT(e.expected(), HasSubstr(c.expected)) << e.what();
    EXPECT_THAT(e.found(), HasSubstr(c.found)) << e.what();
    // The message carries all four parts.
    if (!c.key_path.empty()) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(c.key_path + ": "));
    }
    EXPECT_THAT(std::string(e.what()), HasSubstr("expected " + e.expected()));
    EXPECT_THAT(std::string(e.what()), HasSubstr("found " + e.found()));
  }
}

// ---------------------------------------------------------------------------------------------
// One file per bad-input class, under test/bad/.

class BadFileTest : public SceneTest, public ::testing::WithParamInterface<BadCase> {};

TEST_P(BadFileTest, IsRefusedWithLocationKeyExpectedAndFound) {
  const BadCase& c = GetParam();
  ExpectSceneRefused(kTestDir / "bad" / (c.name + ".yaml"), c, registry_);
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, BadFileTest,
    ::testing::Values(
        BadCase{"missing_unit", 37, 13, "run.duration", "a time (us, ms, s)", "'5' (no unit)"},
        BadCase{"wrong_unit", 14, 45, "parts.shaft.material.youngs_modulus",
                "a pressure (Pa, kPa, MPa, GPa)", "'210 N' (N is a unit of force)"},
        BadCase{"unknown_unit", 36, 9, "run.rate", "a frequency (Hz, kHz)",
                "'2 kHZ' (unknown unit 'kHZ')"},
        BadCase{"unknown_key", 20, 16, "parts.bushing.material.young",
                "one of the keys name, youngs_modulus, poisson", "unknown key 'young'"},
        BadCase{"missing_key", 16, 5, "parts.bushing.material", "key 'material' (required)",
                "only the keys role, size, geometry, form"},
        BadCase{"negative_tolerance", 12, 18, "parts.shaft.form.roundness",
                "a length in [0 m, 20 mm]", "'-4 um'"},
        BadCase{"inverted_limits", 17, 49, "parts.bushing.size.upper",
                "an upper deviation greater than the lower deviation (21 um)",
                "'0 um' (the limits are inverted)"},
        BadCase{"out_of_range", 24, 13, "model.friction", "a dimensionless number in [0, 1.5]",
                "'2.5'"},
        BadCase{"nonexistent_plugin", 4, 10, "surface",
                "a loaded surface plugin id (test.surface.cylinder, test.surface.thread)",
                "'test.surface.conical' ("},
        BadCase{"unknown_law", 23, 8, "model.law",
                "a resistance law that test.surface.cylinder offers (gps, ve1)", "'magic'"},
        BadCase{"yaml_syntax", 10, 9, "", "valid YAML", "end of map flow not found"},
        BadCase{"wrong_type", 40, 12, "run.outputs", "a list", "'trace'"},
        BadCase{"duplicate_roles", 16, 11, "parts.bushing.role",
                "one part with role inner and one with role outer",
                "'inner' for both 'shaft' and 'bushing'"},
        BadCase{"ra_above_rz", 13, 49, "parts.shaft.texture.Rz", "Rz >= Ra (1.6 um)",
                "'0.4 um' (Ra > Rz is physically impossible)"},
        BadCase{"unknown_iso_code", 17, 11, "parts.bushing.size",
                "an ISO 286 tolerance class defined at this nominal size", "'20 mm Q7' ("}),
    [](const ::testing::TestParamInfo<BadCase>& p) { return p.param.name; });

TEST_F(SceneTest, EveryBadFileHasACase) {
  // A file added to bad/ without a case above would never be checked.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kTestDir / "bad")) {
    if (entry.path().extension() == ".yaml") ++files;
  }
  EXPECT_EQ(files, 15);
}

// ---------------------------------------------------------------------------------------------
// Further refusals, each a one-line edit of good/full.yaml written to a temporary file.

struct Variant {
  BadCase expect;
  std::string from;  // text in good/full.yaml, must occur once
  std::string to;
};

std::ostream& operator<<(std::ostream& out, const Variant& v) { return out << v.expect.name; }

std::string ReadFile(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path WriteVariant(const std::string& name, const std::string& from, const std::string& to,
                      const std::string& source = "full.yaml") {
  std::string text = ReadFile(kTestDir / "good" / source);
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from << " occurs twice";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const fs::path dir = fs::path(::testing::TempDir()) / "fitfeel_scene_test";
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << text;
  return file;
}

// good/<source> with each `from` (occurring once) replaced by its `to`, written to a temporary
// file <name>.yaml.
fs::path WriteEdited(const std::string& name, const std::string& source,
                     const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = ReadFile(kTestDir / "good" / source);
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const fs::path dir = fs::path(::testing::TempDir()) / "fitfeel_scene_test";
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << text;
  return file;
}

class VariantTest : public SceneTest, public ::testing::WithParamInterface<Variant> {};

// A run streams its trace and recording to disk: the longest run at the highest rate, with a
// recording, is within its buffers (it was refused once, when the trace was held in memory).
TEST_F(SceneTest, AnHourAtTheHighestRateWithARecordingIsAccepted) {
  const fs::path file =
      WriteEdited("hour_at_10kHz", "full.yaml",
                  {{"rate: 2 kHz", "rate: 10 kHz"}, {"duration: 5 s", "duration: 3600 s"}});
  LoadOptions large;
  large.allow_large = true;  // its outputs, tens of GiB, are over the large-output threshold
  const Scene scene = LoadScene(file, registry_, large);
  EXPECT_EQ(scene.run.duration, 3600.0);
  EXPECT_TRUE(scene.run.write_recording);
  EXPECT_LE(scene.cost.run_bytes, kMaxRunBufferBytes);
}

TEST_P(VariantTest, IsRefused) {
  const Variant& v = GetParam();
  ExpectSceneRefused(WriteVariant(v.expect.name, v.from, v.to), v.expect, registry_);
}

INSTANTIATE_TEST_SUITE_P(
    Refusals, VariantTest,
    ::testing::Values(
        Variant{{"hole_class_on_shaft", 8, 11, "parts.shaft.size", "a shaft tolerance class",
                 "'20 mm H7' (H7 is a hole class)"},
                "size: 20 mm g6",
                "size: 20 mm H7"},
        Variant{{"size_without_class", 8, 11, "parts.shaft.size",
                 "a size as '<nominal> <ISO 286 class>'",
                 "'20 mm' ('mm' is not an ISO 286 tolerance class)"},
                "size: 20 mm g6",
                "size: 20 mm"},
        Variant{{"size_nominal_without_unit", 8, 11, "parts.shaft.size", "a size as",
                 "the nominal size '20' (no unit)"},
                "size: 20 mm g6",
                "size: 20 g6"},
        Variant{{"size_as_list", 8, 11, "parts.shaft.size", "a size as", "a list"},
                "size: 20 mm g6",
                "size: [20 mm, g6]"},
        Variant{{"thread_pitch_not_in_iso261", 8, 11, "parts.shaft.size",
                 "an ISO metric thread designation of ISO 261 and ISO 965-1",
                 "'M10x1.3 6g' (ISO thread 'M10x1.3 6g': 1.3 mm is not an ISO 261 pitch of M10 "
                 "(expected one of 1.5 (coarse), 1.25, 1, 0.75))"},
                "size: 20 mm g6",
                "size: M10x1.3 6g"},
        Variant{{"thread_grade_out_of_range", 8, 11, "parts.shaft.size",
                 "an ISO metric thread designation",
                 "ISO 965-1 has no tolerance grade 2 for the pitch diameter d2 of an external "
                 "thread (grades 3, 4, 5, 6, 7, 8, 9)"},
                "size: 20 mm g6",
                "size: M10 2g"},
        Variant{{"internal_thread_on_shaft", 8, 11, "parts.shaft.size",
                 "an external thread class (position e, f, g or h, e.g. 6g) for an inner part",
                 "'M10x1.25-6H' (6H is an internal thread class)"},
                "size: 20 mm g6",
                "size: M10x1.25-6H"},
        Variant{{"zero_width_limits", 17, 48, "parts.bushing.size.upper",
                 "an upper deviation greater than the lower deviation (0 m)",
                 "(a tolerance zone of zero width)"},
                "upper: 21 um",
                "upper: 0 um"},
        Variant{{"negative_smallest_size", 17, 35, "parts.bushing.size.lower",
                 "a lower deviation above -20 mm", "'-25 mm'"},
                "lower: 0 um",
                "lower: -25 mm"},
        Variant{{"zero_nominal", 17, 21, "parts.bushing.size.nominal", "a length in (0 m, 3.15 m]",
                 "'0 mm'"},
                "nominal: 20 mm",
                "nominal: 0 mm"},
        Variant{{"poisson_above_half", 20, 50, "parts.bushing.material.poisson",
                 "a Poisson's ratio in [0, 0.5)", "'0.7'"},
                "poisson: 0.34",
                "poisson: 0.7"},
        // The laws' range: -0.5 passed the parser once and was refused by the cylinder law.
        Variant{{"poisson_negative", 20, 50, "parts.bushing.material.poisson",
                 "a Poisson's ratio in [0, 0.5)", "'-0.5'"},
                "poisson: 0.34",
                "poisson: -0.5"},
        Variant{{"poisson_half", 20, 50, "parts.bushing.material.poisson",
                 "a Poisson's ratio in [0, 0.5)", "'0.5'"},
                "poisson: 0.34",
                "poisson: 0.5"},
        // What the scheduler and the analyzers would refuse, refused by the loader at its key.
        Variant{{"shorter_than_a_tick", 37, 13, "run.duration", "a run of at least one tick",
                 "'0.1 ms' at 2e+03 Hz"},
                "duration: 5 s",
                "duration: 0.1 ms"},
        Variant{{"depth_table_over_its_cap", 28, 15, "model.depth_step",
                 "fewer than 2e+06 depth-table rows", "'1 nm'"},
                "depth_step: 0.5 mm",
                "depth_step: 1 nm"},
        Variant{{"large_grid_without_allow_large", 26, 15, "model.resolution",
                 "or --allow-large to run it anyway", "cells"},
                "resolution: {rows: 40, columns: 72}",
                "resolution: {rows: 2000, columns: 2000}"},
        Variant{{"modulus_too_small", 20, 32, "parts.bushing.material.youngs_modulus",
                 "a pressure in [1 MPa, 1200 GPa]", "'5 kPa'"},
                "youngs_modulus: 110 GPa",
                "youngs_modulus: 5 kPa"},
        Variant{{"missing_poisson", 20, 15, "parts.bushing.material.poisson",
                 "key 'poisson' (required)", "only the keys youngs_modulus"},
                "110 GPa, poisson: 0.34}",
                "110 GPa}"},
        Variant{{"unsupported_form", 19, 12, "parts.bushing.form.flatness",
                 "a form characteristic that test.surface.cylinder models (axis_straightness, "
                 "generatrix_straightness, roundness, cylindricity)",
                 "'flatness', which this surface type does not model"},
                "cylindricity: 8 um",
                "flatness: 8 um"},
        Variant{
            {"unknown_form", 19, 12, "parts.bushing.form.roundnes",
             "a form characteristic that test.surface.cylinder models", "unknown key 'roundnes'"},
            "cylindricity: 8 um",
            "roundnes: 8 um"},
        Variant{{"form_larger_than_part", 19, 26, "parts.bushing.form.cylindricity",
                 "a length in [0 m, 20 mm]", "'25 mm'"},
                "cylindricity: 8 um",
                "cylindricity: 25 mm"},
        Variant{{"negative_waviness", 13, 25, "parts.shaft.texture.waviness",
                 "a length in [0 m, 1 mm]", "'-3.2 um'"},
                "waviness: 3.2 um",
                "waviness: -3.2 um"},
        Variant{{"ra_without_rz", 13, 14, "parts.shaft.texture.Rz", "Rz >= Ra (0.4 um)",
                 "no Rz (taken as 0)"},
                ", Rz: 1.6 um}",
                "}"},
        Variant{{"rate_too_low", 36, 9, "run.rate", "a frequency in [100 Hz, 10 kHz]", "'50 Hz'"},
                "rate: 2 kHz",
                "rate: 50 Hz"},
        Variant{{"duration_in_hours", 37, 13, "run.duration", "a time (us, ms, s)",
                 "'2 h' (unknown unit 'h')"},
                "duration: 5 s",
                "duration: 2 h"},
        Variant{{"duration_over_an_hour", 37, 13, "run.duration", "a time in (0 s, 3600 s]",
                 "'3601 s'"},
                "duration: 5 s",
                "duration: 3601 s"},
        Variant{{"duration_zero", 37, 13, "run.duration", "a time in (0 s, 3600 s]", "'0 s'"},
                "duration: 5 s",
                "duration: 0 s"},
        Variant{{"negative_seed", 38, 9, "run.seed", kSeedRange, "'-1'"}, "seed: 42", "seed: -1"},
        Variant{
            {"fractional_seed", 38, 9, "run.seed", kSeedRange, "'4.2'"}, "seed: 42", "seed: 4.2"},
        Variant{{"unknown_clock", 39, 10, "run.clock", "one of virtual, realtime", "'wall'"},
                "clock: realtime",
                "clock: wall"},
        Variant{{"unknown_output", 40, 20, "run.outputs[1]", "one of trace, summary, recording",
                 "'video'"},
                "[trace, summary, recording]",
                "[trace, video]"},
        Variant{{"repeated_output", 40, 20, "run.outputs[1]", "each output once",
                 "'trace' a second time"},
                "[trace, summary, recording]",
                "[trace, trace]"},
        Variant{{"static_below_kinetic", 25, 20, "model.static_friction",
                 "a static coefficient at least the sliding one (friction: 0.15)", "0.1"},
                "friction: 0.15\n",
                "friction: 0.15\n  static_friction: 0.1\n"},
        Variant{{"unknown_lubrication", 24, 16, "model.lubrication", "dry", "'oily'"},
                "friction: 0.15",
                "lubrication: oily"},
        Variant{{"yield_above_range", 20, 72, "parts.bushing.material.yield_strength",
                 "a pressure in [1 MPa, 5 GPa]", "'9 GPa'"},
                "poisson: 0.34",
                "poisson: 0.34, yield_strength: 9 GPa"},
        Variant{{"zero_stiffness", 25, 22, "model.contact_stiffness", "a stiffness > 0 N/m",
                 "'0 N/um'"},
                "contact_stiffness: 2 N/um",
                "contact_stiffness: 0 N/um"},
        Variant{{"zero_rows", 26, 22, "model.resolution.rows", "an integer in [1, 10000]", "'0'"},
                "rows: 40",
                "rows: 0"},
        Variant{{"too_many_cells", 26, 15, "model.resolution", "at most 4000000 cells",
                 "5000 x 5000 = 25000000 cells"},
                "{rows: 40, columns: 72}",
                "{rows: 5000, columns: 5000}"},
        Variant{{"resolution_word", 26, 15, "model.resolution", "auto or a map {rows, columns}",
                 "'fine'"},
                "{rows: 40, columns: 72}",
                "fine"},
        Variant{{"depth_step_too_long", 28, 15, "model.depth_step", "a length in (0 m, 20 mm]",
                 "'25 mm'"},
                "depth_step: 0.5 mm",
                "depth_step: 25 mm"},
        Variant{{"texture_mode", 27, 12, "model.texture", "one of expected, sampled", "'random'"},
                "texture: sampled",
                "texture: random"},
        Variant{{"options_not_map", 29, 12, "model.options", "a map of surface-specific options",
                 "'none'"},
                "options: {tabulate: yes}",
                "options: none"},
        Variant{{"options_unknown_key", 29, 13, "model.options.tabluate",
                 "one of the keys tabulate", "unknown key 'tabluate'"},
                "options: {tabulate: yes}",
                "options: {tabluate: yes}"},
        Variant{{"device_unknown_key", 33, 3, "device.radial_lod",
                 "one of the keys plugin, speed, radial_load", "unknown key 'radial_lod'"},
                "radial_load: 2 N",
                "radial_lod: 2 N"},
        Variant{{"device_wrong_unit", 32, 10, "device.speed", "a velocity (mm/s, m/s)",
                 "'10 mm' (mm is a unit of length)"},
                "speed: 10 mm/s",
                "speed: 10 mm"},
        Variant{{"device_plugin_missing", 31, 11, "device.plugin",
                 "a loaded device plugin id (test.device.fake)", "'test.device.phantom' ("},
                "plugin: test.device.fake",
                "plugin: test.device.phantom"},
        Variant{{"surface_id_as_device", 31, 11, "device.plugin", "a loaded device plugin id",
                 "'test.surface.cylinder' ("},
                "plugin: test.device.fake",
                "plugin: test.surface.cylinder"},
        Variant{{"surface_without_forces", 4, 10, "surface", "a surface type that renders forces",
                 "thread resistance laws are not written yet"},
                "surface: test.surface.cylinder",
                "surface: test.surface.thread"},
        Variant{{"moving_names_no_part", 21, 9, "moving", "one of shaft, bushing", "'pin'"},
                "moving: shaft",
                "moving: pin"},
        Variant{{"geometry_checked_by_plugin", 9, 24, "parts.shaft.geometry.length",
                 "a length > 0 m", "'0 mm'"},
                "{length: 60 mm}",
                "{length: 0 mm}"},
        Variant{{"pair_checked_by_plugin", 6, 3, "parts", "parts of the same nominal size",
                 "20 mm and 25 mm"},
                "nominal: 20 mm",
                "nominal: 25 mm"},
        // The safety section is checked when the scene loads, as `run` checks it, so that
        // `validate` refuses it too (it was checked only at run time once).
        Variant{{"safety_checked_when_loaded", 34, 20, "safety.coupling",
                 "one of spring_damper, direct", "'bogus'"},
                "safety: {physical_full_scale: 20 N}",
                "safety: {coupling: bogus}"},
        Variant{{"unknown_top_level_key", 34, 1, "safty", "one of the keys scenario, description",
                 "unknown key 'safty'"},
                "safety: {",
                "safty: {"},
        Variant{{"missing_section", 2, 1, "run", "key 'run' (required)", "only the keys"},
                "run:\n  rate: 2 kHz\n  duration: 5 s\n  seed: 42\n  clock: realtime\n"
                "  outputs: [trace, summary, recording]\n",
                ""},
        Variant{{"repeated_key", 39, 3, "run.seed", "each key once", "'seed' a second time"},
                "clock: realtime",
                "seed: 7"},
        Variant{{"scenario_name_with_space", 2, 11, "scenario", "a scenario name of letters",
                 "'good h7g6'"},
                "scenario: good-h7g6",
                "scenario: good h7g6"},
        Variant{
            {"one_part", 6, 3, "parts", "exactly two parts", "1 part (shaft)"},
            "  bushing:\n    role: outer\n    size: {nominal: 20 mm, lower: 0 um, upper: 21 um}\n"
            "    geometry: {length: 20 mm, outer_diameter: 30 mm}\n"
            "    form: {cylindricity: 8 um}\n"
            "    material: {youngs_modulus: 110 GPa, poisson: 0.34}\n",
            ""},
        Variant{
            {"three_parts", 6, 3, "parts", "exactly two parts", "3 parts (shaft, bushing, spare)"},
            "moving: shaft",
            "  spare: {role: inner}\nmoving: shaft"},
        Variant{{"role_misspelt", 16, 11, "parts.bushing.role", "one of inner, outer", "'outter'"},
                "role: outer",
                "role: outter"}),
    [](const ::testing::TestParamInfo<Variant>& p) { return p.param.expect.name; });

TEST_F(SceneTest, LargeGridIsAcceptedWhenAllowedWithItsCost) {
  LoadOptions options;
  options.allow_large = true;
  const Scene scene = LoadScene(WriteVariant("large_allowed", "resolution: {rows: 40, columns: 72}",
                                             "resolution: {rows: 2000, columns: 2000}"),
                                registry_, options);
  EXPECT_EQ(scene.cost.inner_cells, 4'000'000);
  EXPECT_GT(scene.cost.prepare_bytes, kLargeSceneBytes);
}

TEST_F(SceneTest, CarriageReturnOnlyLineEndingsReadAsLines) {
  std::string text = ReadFile(kTestDir / "good" / "full.yaml");
  for (char& c : text) {
    if (c == '\n') c = '\r';
  }
  const fs::path file = fs::path(::testing::TempDir()) / "fitfeel_scene_cr.yaml";
  std::ofstream(file, std::ios::binary) << text;
  const Scene scene = LoadScene(file, registry_);
  EXPECT_EQ(scene.run.duration, 5.0);
  // Line numbers stay those an editor shows.
  const fs::path bad = WriteVariant("cr_bad", "duration: 5 s", "duration: 5");
  std::string bad_text = ReadFile(bad);
  for (char& c : bad_text) {
    if (c == '\n') c = '\r';
  }
  std::ofstream(bad, std::ios::binary) << bad_text;
  ExpectSceneRefused(bad, {"cr_bad", 37, 13, "run.duration", "a time", "'5'"}, registry_);
}

TEST_F(SceneTest, FileLevelProblemsAreScenarioErrors) {
  const fs::path dir = fs::path(::testing::TempDir()) / "fitfeel_scene_files";
  fs::create_directories(dir);
  const fs::path missing = dir / "does_not_exist.yaml";
  fs::remove(missing);
  ExpectSceneRefused(missing, {"missing", 0, 0, "", "a readable scenario file", "No such file"},
                     registry_);
  const fs::path empty = dir / "empty.yaml";
  std::ofstream(empty) << "";
  ExpectSceneRefused(empty, {"empty", 0, 0, "", "a map of scenario keys", "an empty file"},
                     registry_);
  const fs::path two = dir / "two.yaml";
  std::ofstream(two) << "scenario: a\n---\nscenario: b\n";
  ExpectSceneRefused(two, {"two", 3, 1, "", "one scene per file", "a second document"}, registry_);
  const fs::path list = dir / "list.yaml";
  std::ofstream(list) << "- scenario: a\n";
  ExpectSceneRefused(list, {"list", 1, 1, "", "a map of scenario keys", "a list"}, registry_);
  ExpectSceneRefused(dir, {"dir", 0, 0, "", "a scenario file", "a directory"}, registry_);
}

// ---------------------------------------------------------------------------------------------
// Good scenes, parsed into SI.

TEST_F(SceneTest, FullScenarioIsParsedIntoSi) {
  const fs::path file = kTestDir / "good" / "full.yaml";
  const Scene scene = LoadScene(file, registry_);
  EXPECT_EQ(scene.file, file);
  EXPECT_EQ(scene.name, "good-h7g6");
  EXPECT_EQ(scene.description, "shaft 20 mm g6 into bushing 20 mm H7");
  EXPECT_EQ(scene.surface_id, "test.surface.cylinder");
  ASSERT_NE(scene.surface, nullptr);

  const PartSpec& shaft = scene.inner;
  EXPECT_EQ(shaft.name, "shaft");
  EXPECT_EQ(shaft.role, Role::kInner);
  // 20 g6 (ISO 286-2, 18-30 mm): es = -7 um, ei = -20 um.
  EXPECT_DOUBLE_EQ(shaft.size.nominal, 0.020);
  EXPECT_NEAR(shaft.size.upper_deviation, -7e-6, 1e-12);
  EXPECT_NEAR(shaft.size.lower_deviation, -20e-6, 1e-12);
  EXPECT_EQ(shaft.size.iso_code, "g6");
  EXPECT_EQ(shaft.form.tolerance.size(), 2u);
  EXPECT_EQ(shaft.form.Get(FormCharacteristic::kAxisStraightness), 10e-6);
  EXPECT_EQ(shaft.form.Get(FormCharacteristic::kRoundness), 4e-6);
  EXPECT_EQ(shaft.texture.waviness, 3.2e-6);
  EXPECT_EQ(shaft.texture.ra, 0.4e-6);
  EXPECT_EQ(shaft.texture.rz, 1.6e-6);
  EXPECT_EQ(shaft.material.name, "C45E4");
  EXPECT_EQ(shaft.material.youngs_modulus, 210e9);
  EXPECT_EQ(shaft.material.poisson, 0.3);
  ASSERT_NE(shaft.geometry, nullptr);
  EXPECT_EQ(shaft.geometry->mating_length(), 0.060);

  const PartSpec& bushing = scene.outer;
  EXPECT_EQ(bushing.name, "bushing");
  EXPECT_EQ(bushing.role, Role::kOuter);
  EXPECT_EQ(bushing.size.nominal, 0.020);
  EXPECT_EQ(bushing.size.lower_deviation, 0.0);
  EXPECT_EQ(bushing.size.upper_deviation, 21e-6);
  EXPECT_EQ(bushing.size.iso_code, "");
  EXPECT_EQ(bushing.form.Get(FormCharacteristic::kCylindricity), 8e-6);
  EXPECT_EQ(bushing.texture.ra, 0.0);
  EXPECT_EQ(bushing.material.name, "");
  EXPECT_EQ(bushing.material.youngs_modulus, 110e9);
  EXPECT_EQ(bushing.material.poisson, 0.34);
  EXPECT_EQ(bushing.geometry->mating_length(), 0.020);

  EXPECT_EQ(scene.moving, Role::kInner);
  EXPECT_EQ(scene.model.law, "ve1");
  EXPECT_EQ(scene.model.friction, 0.15);
  EXPECT_EQ(scene.model.contact_stiffness, 2e6);
  EXPECT_EQ(scene.model.resolution.rows, 40);
  EXPECT_EQ(scene.model.resolution.columns, 72);
  EXPECT_EQ(scene.model.texture, TextureMode::kSampled);
  EXPECT_EQ(scene.model.depth_step, 0.5e-3);
  ASSERT_NE(scene.model.options, nullptr);
  EXPECT_TRUE(OptionsAs<test::FakeOptions>(scene.model.options).tabulate);

  EXPECT_EQ(scene.device_id, "test.device.fake");
  ASSERT_NE(scene.device, nullptr);
  DeviceState state;
  scene.device->Read(2.0, &state);  // the fake moves at the configured speed
  EXPECT_DOUBLE_EQ(state.position.y(), 2.0 * 0.010);

  ASSERT_TRUE(scene.safety.has_value());
  ASSERT_TRUE(scene.safety->settings.physical_full_scale.has_value());
  EXPECT_EQ(*scene.safety->settings.physical_full_scale, 20.0);

  EXPECT_EQ(scene.run.rate, 2000.0);
  EXPECT_EQ(scene.run.duration, 5.0);
  EXPECT_EQ(scene.run.seed, 42u);
  EXPECT_EQ(scene.run.clock, ClockMode::kRealTime);
  EXPECT_TRUE(scene.run.write_trace);
  EXPECT_TRUE(scene.run.write_summary);
  EXPECT_TRUE(scene.run.write_recording);
}

TEST_F(SceneTest, MinimalScenarioTakesTheDocumentedDefaults) {
  const Scene scene = LoadScene(kTestDir / "good" / "minimal.yaml", registry_);
  EXPECT_EQ(scene.name, "minimal");
  EXPECT_EQ(scene.description, "");
  // 20 js6: +-IT6/2 = +-6.5 um; 20 H7: 0 .. +21 um (ISO 286-2, 18-30 mm).
  EXPECT_NEAR(scene.inner.size.lower_deviation, -6.5e-6, 1e-12);
  EXPECT_NEAR(scene.inner.size.upper_deviation, 6.5e-6, 1e-12);
  EXPECT_NEAR(scene.outer.size.lower_deviation, 0.0, 1e-12);
  EXPECT_NEAR(scene.outer.size.upper_deviation, 21e-6, 1e-12);
  EXPECT_EQ(scene.outer.size.iso_code, "H7");
  EXPECT_TRUE(scene.inner.form.tolerance.empty());
  EXPECT_EQ(scene.inner.texture.rz, 0.0);
  EXPECT_EQ(scene.moving, Role::kOuter);
  EXPECT_EQ(scene.model.law, "gps");  // the surface's first law
  EXPECT_EQ(scene.model.contact_stiffness, 500e3);
  EXPECT_TRUE(scene.model.resolution.is_auto());
  EXPECT_EQ(scene.model.texture, TextureMode::kExpected);
  EXPECT_EQ(scene.model.depth_step, 0.0);
  EXPECT_EQ(scene.model.options, nullptr);
  EXPECT_FALSE(OptionsAs<test::FakeOptions>(scene.model.options).tabulate);
  EXPECT_FALSE(scene.safety.has_value());
  EXPECT_EQ(scene.run.rate, 1000.0);
  EXPECT_EQ(scene.run.duration, 0.25);
  EXPECT_EQ(scene.run.seed, 1u);
  EXPECT_EQ(scene.run.clock, ClockMode::kVirtual);
  EXPECT_TRUE(scene.run.write_trace);
  EXPECT_TRUE(scene.run.write_summary);
  EXPECT_FALSE(scene.run.write_recording);
}

// docs/friction.md: one coefficient names mu_k = mu_s; none takes the handbook pair of the
// lubrication (Marks': hard steel, dry 0.78 / 0.42, greasy middles 0.17 / 0.075).
TEST_F(SceneTest, FrictionKeysTakeTheDocumentedDefaults) {
  const Scene one = LoadScene(kTestDir / "good" / "minimal.yaml", registry_);
  EXPECT_EQ(one.model.friction, 0.1);
  EXPECT_EQ(one.model.static_friction, 0.1);
  EXPECT_EQ(one.model.breakaway_displacement, 2e-6);
  const Scene dry = LoadScene(
      WriteVariant("dry", "  friction: 0.1\n", "  lubrication: dry\n", "minimal.yaml"), registry_);
  EXPECT_EQ(dry.model.friction, 0.42);
  EXPECT_EQ(dry.model.static_friction, 0.78);
  const Scene lubricated =
      LoadScene(WriteVariant("lubricated", "  friction: 0.1\n", "", "minimal.yaml"), registry_);
  EXPECT_EQ(lubricated.model.friction, 0.075);
  EXPECT_EQ(lubricated.model.static_friction, 0.17);
  const Scene both = LoadScene(
      WriteVariant("both", "  friction: 0.1\n",
                   "  friction: 0.1\n  static_friction: 0.2\n  breakaway_displacement: 5 um\n",
                   "minimal.yaml"),
      registry_);
  EXPECT_EQ(both.model.static_friction, 0.2);
  EXPECT_NEAR(both.model.breakaway_displacement, 5e-6, 1e-18);
  const Scene auto_k = LoadScene(WriteVariant("auto_k", "contact_stiffness: 500 N/mm",
                                              "contact_stiffness: auto", "minimal.yaml"),
                                 registry_);
  EXPECT_EQ(auto_k.model.contact_stiffness, 0.0);
  const Scene yield = LoadScene(
      WriteVariant("yield", "poisson: 0.34", "poisson: 0.34, yield_strength: 430 MPa"), registry_);
  EXPECT_EQ(yield.outer.material.yield_strength, 430e6);
  EXPECT_EQ(one.outer.material.yield_strength, 0.0);
}

TEST_F(SceneTest, NonRenderingSurfaceOnlyWhenAllowed) {
  const fs::path file = WriteVariant("thread", "surface: test.surface.cylinder",
                                     "surface: test.surface.thread", "minimal.yaml");
  EXPECT_THROW(LoadScene(file, registry_), ScenarioError);
  LoadOptions options;
  options.allow_non_rendering = true;
  const Scene scene = LoadScene(file, registry_, options);
  EXPECT_EQ(scene.surface_id, "test.surface.thread");
  EXPECT_FALSE(scene.surface->renders_forces());
  EXPECT_EQ(scene.model.law, "");
  // A law cannot be named for a surface that offers none.
  const fs::path with_law = WriteVariant("thread_law", "  friction: 0.1\n",
                                         "  law: gps\n  friction: 0.1\n", "minimal.yaml");
  std::string text = ReadFile(with_law);
  text.replace(text.find("test.surface.cylinder"), 21, "test.surface.thread");
  std::ofstream(with_law) << text;
  ExpectSceneRefused(with_law,
                     {"thread_law", 17, 8, "model.law",
                      "a resistance law that test.surface.thread "
                      "offers (none)",
                      "'gps'"},
                     registry_, options);
}

// A threaded pair sized by ISO thread designations: the pitch diameter's limits as the size, the
// crest's beside them (ISO 965-2: M10x1.5 6g d2 -32/-164 um, d -32/-268 um; 6H D2 0/+180 um,
// D1 0/+300 um).
TEST_F(SceneTest, ThreadDesignationsSizeAThreadedPair) {
  const fs::path file = WriteEdited("thread_designations", "minimal.yaml",
                                    {{"test.surface.cylinder", "test.surface.thread"},
                                     {"size: 20 mm js6", "size: M10x1.5 6g"},
                                     {"size: 20 mm H7", "size: M10 6H"}});
  LoadOptions options;
  options.allow_non_rendering = true;
  const Scene scene = LoadScene(file, registry_, options);
  const SizeSpec& bolt = scene.inner.size;
  EXPECT_EQ(bolt.iso_code, "M10x1.5 6g");
  EXPECT_EQ(bolt.nominal, 0.010);
  EXPECT_NEAR(bolt.pitch, 1.5e-3, 1e-15);
  EXPECT_NEAR(bolt.upper_deviation, -32e-6, 1e-12);
  EXPECT_NEAR(bolt.lower_deviation, -164e-6, 1e-12);
  EXPECT_NEAR(bolt.crest_upper_deviation, -32e-6, 1e-12);
  EXPECT_NEAR(bolt.crest_lower_deviation, -268e-6, 1e-12);
  const SizeSpec& nut = scene.outer.size;
  EXPECT_EQ(nut.iso_code, "M10x1.5 6H");
  EXPECT_NEAR(nut.lower_deviation, 0.0, 1e-12);
  EXPECT_NEAR(nut.upper_deviation, 180e-6, 1e-12);
  EXPECT_NEAR(nut.crest_lower_deviation, 0.0, 1e-12);
  EXPECT_NEAR(nut.crest_upper_deviation, 300e-6, 1e-12);
  // A plain size has no pitch.
  EXPECT_EQ(LoadScene(kTestDir / "good" / "minimal.yaml", registry_).inner.size.pitch, 0.0);
  // An outer part with an external class is refused at its size.
  ExpectSceneRefused(WriteEdited("thread_designations", "minimal.yaml",
                                 {{"test.surface.cylinder", "test.surface.thread"},
                                  {"size: 20 mm js6", "size: M10x1.5 6g"},
                                  {"size: 20 mm H7", "size: M10 6g"}}),
                     {"thread_designations", 12, 11, "parts.hole.size",
                      "an internal thread class (position G or H, e.g. 6H) for an outer part",
                      "'M10 6g' (6g is an external thread class)"},
                     registry_, options);
}

TEST_F(SceneTest, EmptyOutputListWritesNothing) {
  const Scene scene =
      LoadScene(WriteVariant("no_outputs", "[trace, summary, recording]", "[]"), registry_);
  EXPECT_FALSE(scene.run.write_trace);
  EXPECT_FALSE(scene.run.write_summary);
  EXPECT_FALSE(scene.run.write_recording);
}

TEST_F(SceneTest, SummaryNamesPartsLimitsModelDeviceAndRun) {
  const std::string summary = DescribeScene(LoadScene(kTestDir / "good" / "full.yaml", registry_));
  EXPECT_THAT(summary, HasSubstr("scenario     good-h7g6 ("));
  EXPECT_THAT(summary, HasSubstr("inner      shaft (moving)\n"));
  EXPECT_THAT(summary, HasSubstr("size 20 mm g6: deviations -20 .. -7 um (limits 19.9800 .. "
                                 "19.9930 mm)"));
  EXPECT_THAT(summary, HasSubstr("outer      bushing\n"));
  EXPECT_THAT(summary, HasSubstr("size 20 mm: deviations +0 .. +21 um"));
  EXPECT_THAT(summary, HasSubstr("form axis_straightness 10 um, roundness 4 um\n"));
  EXPECT_THAT(summary, HasSubstr("texture waviness 3.2 um, Ra 0.4 um, Rz 1.6 um\n"));
  EXPECT_THAT(summary, HasSubstr("material C45E4, E 210 GPa, nu 0.3\n"));
  EXPECT_THAT(summary, HasSubstr("geometry cylinder d=20 mm l=60 mm\n"));
  EXPECT_THAT(summary, HasSubstr("law ve1, friction 0.15 (static 0.15, breakaway 2 um), contact "
                                 "stiffness 2 N/um, resolution 40 x 72, texture sampled, depth "
                                 "step 500 um\n"));
  EXPECT_THAT(summary, HasSubstr("texture none given (smooth)\n"));
  EXPECT_THAT(summary, HasSubstr("device       test.device.fake\n"));
  EXPECT_THAT(summary, HasSubstr("run          2 kHz for 5 s (10000 ticks), seed 42, clock "
                                 "realtime, outputs trace, summary, recording\n"));
  // 40 x 72 cells a part; the fake law has no estimate of its own.
  EXPECT_THAT(summary, HasSubstr("cost         2880 + 2880 cells, "));
  EXPECT_THAT(summary, Not(HasSubstr("the law's")));
}

}  // namespace
}  // namespace fitfeel
