#include "framework/scenario/scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/line_endings.h"
#include "framework/core/quantity.h"
#include "framework/model/measured_surface.h"
#include "framework/plugin/registry.h"
#include "framework/safety/safety_settings.h"
#include "framework/scenario/cad_parts.h"
#include "framework/scenario/part_parser.h"
#include "framework/scenario/scene_sections.h"
#include "framework/scenario/yaml_file.h"

namespace fitfeel {
namespace scenario {

// No upper limit on a quantity (a name no other framework source gives a file-private constant:
// the unity build compiles several sources as one).
constexpr double kUnlimited = std::numeric_limits<double>::infinity();

// The scheduler's rate: below 100 Hz a haptic loop is felt as vibration, above 10 kHz no device
// or OS timer keeps the period.
constexpr double kMinRate = 100.0;
constexpr double kMaxRate = 10e3;
// A run is a session at a device or a batch computation; an hour bounds one session. The run
// streams its trace to disk, so what it holds per tick stays within the buffer cap at any rate.
constexpr double kMaxDuration = 3600.0;
// Coulomb coefficients of dry or lubricated metal and polymer pairs stay below about 1.5.
constexpr double kMaxFriction = 1.5;
// Grid bounds: a row or column count above 10000, or more than four million cells, would not be
// prepared within the design card's second and describes no feature of a machined surface.
constexpr long kMaxGridSide = 10000;
constexpr long kMaxGridCells = 4'000'000;

std::string ThreeDigits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string JoinList(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out.empty() ? "none" : out;
}

std::vector<std::string> LoadedIds(const PluginRegistry& registry, FitfeelPluginKind kind) {
  std::vector<std::string> ids;
  for (const PluginInfo& info : registry.plugins()) {
    if (info.kind == kind) ids.push_back(info.id);
  }
  return ids;
}

// Names end up in output paths and summaries, so they stay portable.
bool IsPlainName(const std::string& name) {
  if (name.empty()) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

std::shared_ptr<SurfaceType> ResolveSurface(const ConfigNode& node, const PluginRegistry& registry,
                                            const LoadOptions& options, std::string* id) {
  *id = node.AsString();
  std::shared_ptr<SurfaceType> surface;
  try {
    surface = registry.MakeSurface(*id);
  } catch (const PluginError& e) {
    node.Fail(
        "a loaded surface plugin id (" + JoinList(LoadedIds(registry, kFitfeelSurfacePlugin)) + ")",
        node.Describe() + " (" + e.what() + ")");
  }
  if (surface == nullptr) throw std::logic_error("plugin registry returned no surface object");
  if (!surface->renders_forces() && !options.allow_non_rendering) {
    node.Fail("a surface type that renders forces",
              node.Describe() + ", which cannot yet: " + surface->limitation());
  }
  if (surface->law_names().empty() && !options.allow_non_rendering) {
    node.Fail("a surface type that offers a resistance law", node.Describe() + " offers none");
  }
  return surface;
}

Parts ParseParts(const ConfigNode& node, const ConfigNode& moving_node, const SurfaceType& surface,
                 const std::string& surface_id) {
  const std::vector<std::string> names = node.Keys();
  if (names.size() != 2) {
    node.Fail("exactly two parts, one with role inner and one with role outer",
              std::to_string(names.size()) + " part" + (names.size() == 1 ? "" : "s") +
                  (names.empty() ? "" : " (" + JoinList(names) + ")"));
  }
  // Roles first, so a duplicate is reported before either part's details.
  std::vector<Role> roles;
  for (const std::string& name : names) {
    const ConfigNode part = node.Child(name);
    if (!IsPlainName(name)) {
      part.Fail("a part name of letters, digits, '_', '-' or '.'", "'" + name + "'");
    }
    if (!part.is_map()) part.Fail("a map describing the part (role, size, ...)", part.Describe());
    const ConfigNode role = part.Child("role");
    roles.push_back(role.AsOneOf({"inner", "outer"}) == "inner" ? Role::kInner : Role::kOuter);
    if (roles.size() == 2 && roles[0] == roles[1]) {
      role.Fail("one part with role inner and one with role outer",
                role.Describe() + " for both '" + names[0] + "' and '" + names[1] + "'");
    }
  }
  Parts parts;
  for (const std::string& name : names) {
    const ConfigNode node_of_part = node.Child(name);
    PartSpec part = scenario::ParsePart(name, node_of_part, surface, surface_id);
    // The plugin sees everything else the scenario said of the part (size, form, ...).
    const ConfigNode geometry = node_of_part.Child("geometry");
    part.geometry = Located(geometry, "a geometry the surface type accepts",
                            [&] { return surface.ParseGeometry(part, geometry); });
    if (part.geometry == nullptr) {
      throw std::logic_error("surface plugin " + surface_id + " returned no geometry for part '" +
                             name + "'");
    }
    (part.role == Role::kInner ? parts.inner : parts.outer) = std::move(part);
  }
  Located(node, "a pair of parts the surface type accepts",
          [&] { surface.CheckPair(parts.inner, parts.outer, node); });
  const std::string moving = moving_node.AsOneOf({names[0], names[1]});
  parts.moving = moving == parts.inner.name ? Role::kInner : Role::kOuter;
  return parts;
}

Resolution ParseResolution(const ConfigNode& node) {
  const char* const expected = "auto or a map {rows, columns} of positive integers";
  if (node.is_scalar()) {
    if (node.AsString() == "auto") return Resolution{};
    node.Fail(expected, node.Describe());
  }
  if (!node.is_map()) node.Fail(expected, node.Describe());
  node.ExpectOnlyKeys({"rows", "columns"});
  Resolution resolution;
  resolution.rows = static_cast<int>(node.Child("rows").AsInteger(1, kMaxGridSide));
  resolution.columns = static_cast<int>(node.Child("columns").AsInteger(1, kMaxGridSide));
  const long cells = static_cast<long>(resolution.rows) * resolution.columns;
  if (cells > kMaxGridCells) {
    node.Fail("at most " + std::to_string(kMaxGridCells) + " cells (rows x columns)",
              std::to_string(resolution.rows) + " x " + std::to_string(resolution.columns) + " = " +
                  std::to_string(cells) + " cells");
  }
  return resolution;
}

// Friction (docs/friction.md): `friction` is the sliding coefficient mu_k, `static_friction` the
// breakaway one mu_s >= mu_k. A scene that names neither gets the handbook pair of its
// `lubrication` (dry or lubricated hard steel, friction.h); one that names only mu_k gets
// mu_s = mu_k (Coulomb friction with stiction at that level), since a handbook ratio applied to a
// coefficient from elsewhere would be a guess.
void ParseFriction(const ConfigNode& node, ModelSettings* model) {
  bool dry = false;
  std::optional<ConfigNode> lubrication = node.Find("lubrication");
  if (lubrication) dry = lubrication->AsOneOf({"dry", "lubricated"}) == "dry";
  std::optional<ConfigNode> kinetic = node.Find("friction");
  std::optional<ConfigNode> stat = node.Find("static_friction");
  if (kinetic) {
    model->friction = kinetic->AsQuantityIn(Dimension::kDimensionless, 0.0, kMaxFriction);
  } else {
    model->friction = dry ? kDrySteelKineticFriction : kLubricatedSteelKineticFriction;
  }
  if (stat) {
    model->static_friction = stat->AsQuantityIn(Dimension::kDimensionless, 0.0, kMaxFriction);
    if (model->static_friction < model->friction) {
      stat->Fail("a static coefficient at least the sliding one (friction: " +
                     FormatQuantity(model->friction, Dimension::kDimensionless) + ")",
                 stat->Describe());
    }
  } else if (kinetic) {
    model->static_friction = model->friction;
  } else {
    model->static_friction = dry ? kDrySteelStaticFriction : kLubricatedSteelStaticFriction;
  }
  if (std::optional<ConfigNode> z = node.Find("breakaway_displacement")) {
    // Junction deflections are micrometres; 1 mm would be a spring, not friction.
    model->breakaway_displacement = z->AsQuantityIn(Dimension::kLength, 0.0, 1e-3,
                                                    /*min_inclusive=*/false);
  }
}

ModelSettings ParseModel(const ConfigNode& node, const SurfaceType& surface,
                         const std::string& surface_id, const Parts& parts) {
  node.ExpectOnlyKeys({"law", "friction", "static_friction", "lubrication",
                       "breakaway_displacement", "contact_stiffness", "resolution", "texture",
                       "depth_step", "options"});
  ModelSettings model;
  const std::vector<std::string> laws = surface.law_names();
  // Empty only for a surface type loaded for inspection (LoadOptions::allow_non_rendering).
  if (!laws.empty()) model.law = laws.front();
  if (std::optional<ConfigNode> law = node.Find("law")) {
    model.law = law->AsString();
    if (std::find(laws.begin(), laws.end(), model.law) == laws.end()) {
      law->Fail("a resistance law that " + surface_id + " offers (" + JoinList(laws) + ")",
                law->Describe());
    }
  }
  ParseFriction(node, &model);
  // `auto`: the law derives it from its own elastic model (0 in ModelSettings).
  const ConfigNode stiffness = node.Child("contact_stiffness");
  model.contact_stiffness = stiffness.is_scalar() && stiffness.AsString() == "auto"
                                ? 0.0
                                : stiffness.AsQuantityIn(Dimension::kStiffness, 0.0, kUnlimited,
                                                         /*min_inclusive=*/false);
  if (std::optional<ConfigNode> resolution = node.Find("resolution")) {
    model.resolution = ParseResolution(*resolution);
  }
  if (std::optional<ConfigNode> texture = node.Find("texture")) {
    const std::string mode = texture->AsOneOf({"expected", "sampled", "din7190"});
    model.texture = mode == "expected"  ? TextureMode::kExpected
                    : mode == "sampled" ? TextureMode::kSampled
                                        : TextureMode::kDin7190;
  }
  if (std::optional<ConfigNode> step = node.Find("depth_step")) {
    if (!(step->is_scalar() && step->AsString() == "auto")) {
      // A tabulation step longer than the engagement would leave a table of a single entry.
      const double longest =
          std::min(parts.inner.geometry->mating_length(), parts.outer.geometry->mating_length());
      model.depth_step =
          step->AsQuantityIn(Dimension::kLength, 0.0, longest > 0.0 ? longest : kUnlimited,
                             /*min_inclusive=*/false);
    }
  }
  if (std::optional<ConfigNode> options = node.Find("options")) {
    model.options = Located(*options, "options the surface type accepts",
                            [&] { return surface.ParseOptions(*options); });
  }
  surface.CheckModel(parts.inner, parts.outer, model, node);
  return model;
}

ScrewTurn ParseTurn(const ConfigNode& node) {
  if (!node.is_map()) node.Fail("a map {speed, until}", node.Describe());
  node.ExpectOnlyKeys({"speed", "until"});
  ScrewTurn turn;
  turn.speed = node.Child("speed").AsQuantityIn(Dimension::kAngularVelocity, 0.0, kMaxTurnSpeed,
                                                /*min_inclusive=*/false);
  if (std::optional<ConfigNode> until = node.Find("until")) {
    const char* const expected = "a map with one of torque, angle (past the face) or preload";
    if (!until->is_map() || until->Keys().size() != 1) until->Fail(expected, until->Describe());
    until->ExpectOnlyKeys({"torque", "angle", "preload"});
    if (auto torque = until->Find("torque")) {
      turn.target = TurnTarget::kTorque;
      turn.value = torque->AsQuantityIn(Dimension::kTorque, 0.0, kMaxAppliedTorque, false);
    } else if (auto angle = until->Find("angle")) {
      turn.target = TurnTarget::kAngle;
      turn.value = angle->AsQuantityIn(Dimension::kAngle, 0.0, 100.0, false);
    } else {
      turn.target = TurnTarget::kPreload;
      turn.value = until->Child("preload").AsQuantityIn(Dimension::kForce, 0.0, 1e7, false);
    }
  }
  return turn;
}

PartMotionSettings ParsePartMotion(const ConfigNode& node) {
  if (!node.is_map()) {
    node.Fail(
        "a map with the keys radial, damping, radial_load, rotation, torque, turn, axial_load, "
        "tilt and grip_lever",
        node.Describe());
  }
  node.ExpectOnlyKeys({"radial", "damping", "radial_load", "rotation", "torque", "turn",
                       "axial_load", "tilt", "grip_lever"});
  PartMotionSettings motion;
  if (std::optional<ConfigNode> rotation = node.Find("rotation")) {
    motion.rotation = rotation->AsOneOf({"held", "free"}) == "held" ? RotationMotion::kHeld
                                                                    : RotationMotion::kFree;
  }
  if (std::optional<ConfigNode> torque = node.Find("torque")) {
    if (motion.rotation != RotationMotion::kFree) {
      torque->Fail("a torque only with rotation: free (a held part's torque is the holder's)",
                   torque->Describe());
    }
    const auto value = [](const ConfigNode& n) {
      return n.AsQuantityIn(Dimension::kTorque, -kMaxAppliedTorque, kMaxAppliedTorque);
    };
    if (torque->is_scalar()) {
      motion.torque.push_back({0.0, value(*torque)});
    } else {
      const char* const expected = "a torque, or a list of {time, torque} with times increasing";
      if (!torque->is_sequence()) torque->Fail(expected, torque->Describe());
      for (const ConfigNode& item : torque->Items()) {
        if (!item.is_map()) item.Fail("a map {time, torque}", item.Describe());
        item.ExpectOnlyKeys({"time", "torque"});
        const ConfigNode time = item.Child("time");
        TorquePoint point{time.AsQuantityIn(Dimension::kTime, 0.0, kMaxDuration),
                          value(item.Child("torque"))};
        if (!motion.torque.empty() && !(point.time > motion.torque.back().time)) {
          time.Fail("a time after the previous point's", time.Describe());
        }
        motion.torque.push_back(point);
      }
      if (motion.torque.empty()) torque->Fail(expected, "an empty list");
    }
  }
  if (std::optional<ConfigNode> radial = node.Find("radial")) {
    const std::string name = radial->AsOneOf({"held", "quasi_static", "dynamic"});
    motion.radial = name == "held"           ? RadialMotion::kHeld
                    : name == "quasi_static" ? RadialMotion::kQuasiStatic
                                             : RadialMotion::kDynamic;
  }
  if (std::optional<ConfigNode> damping = node.Find("damping")) {
    motion.damping = damping->AsQuantityIn(Dimension::kDamping, 0.0, kMaxPartDamping);
  }
  if (std::optional<ConfigNode> load = node.Find("radial_load")) {
    motion.radial_load = load->AsQuantityIn(Dimension::kForce, 0.0, kMaxRadialLoad);
  }
  if (std::optional<ConfigNode> turn = node.Find("turn")) motion.turn = ParseTurn(*turn);
  if (std::optional<ConfigNode> load = node.Find("axial_load")) {
    motion.axial_load = load->AsQuantityIn(Dimension::kForce, -kMaxRadialLoad, kMaxRadialLoad);
  }
  if (std::optional<ConfigNode> lever = node.Find("grip_lever")) {
    motion.grip_lever = lever->AsQuantityIn(Dimension::kLength, 1e-3, 1.0);
  }
  if (std::optional<ConfigNode> tilt = node.Find("tilt")) {
    // Beyond 10 deg a part is not started on its mate but beside it.
    motion.tilt = tilt->AsQuantityIn(Dimension::kAngle, -0.175, 0.175);
  }
  return motion;
}

// The scheduler's own limits on a run's length, checked here so that `validate` refuses what
// `run` would.
void CheckTicks(const ConfigNode& duration, const RunSettings& run) {
  const double ticks = std::round(run.duration * run.rate);
  if (ticks < 1.0) {
    duration.Fail(
        "a run of at least one tick (1 / run.rate = " + ThreeDigits(1.0 / run.rate) + " s)",
        duration.Describe() + " at " + ThreeDigits(run.rate) + " Hz");
  }
}

double ParseDuration(const ConfigNode& node) {
  return node.AsQuantityIn(Dimension::kTime, 0.0, kMaxDuration, /*min_inclusive=*/false);
}

RunSettings ParseRun(const ConfigNode& node, bool sequence) {
  if (sequence) {
    node.ExpectOnlyKeys({"rate", "seed", "clock", "outputs"});
  } else {
    node.ExpectOnlyKeys({"rate", "duration", "seed", "clock", "outputs"});
  }
  RunSettings run;
  if (std::optional<ConfigNode> rate = node.Find("rate")) {
    run.rate = rate->AsQuantityIn(Dimension::kFrequency, kMinRate, kMaxRate);
  }
  if (!sequence) run.duration = ParseDuration(node.Child("duration"));
  if (std::optional<ConfigNode> seed = node.Find("seed")) {
    run.seed = seed->AsSeed();
  }
  if (std::optional<ConfigNode> clock = node.Find("clock")) {
    run.clock = clock->AsOneOf({"virtual", "realtime"}) == "virtual" ? ClockMode::kVirtual
                                                                     : ClockMode::kRealTime;
  }
  if (std::optional<ConfigNode> outputs = node.Find("outputs")) {
    run.write_trace = run.write_summary = run.write_recording = false;
    std::vector<std::string> seen;
    for (const ConfigNode& item : outputs->Items()) {
      const std::string output = item.AsOneOf({"trace", "summary", "recording"});
      if (std::find(seen.begin(), seen.end(), output) != seen.end()) {
        item.Fail("each output once", item.Describe() + " a second time");
      }
      seen.push_back(output);
      if (output == "trace") run.write_trace = true;
      if (output == "summary") run.write_summary = true;
      if (output == "recording") run.write_recording = true;
    }
  }
  if (!sequence) CheckTicks(node.Child("duration"), run);
  static_assert(kMaxDuration * kMaxRate * kStreamBytesPerTick <= kMaxRunBufferBytes,
                "the longest run at the highest rate fits the scheduler's buffer cap");
  return run;
}

// Prepare's cost model, measured with `fitfeel run` on paper-case1-h7g6 at 40 x 360, 200 x 1440
// and 400 x 3600 cells per part (docs/scenario-format.md, "Cost admission"): peak memory grows
// by about 160 B per cell (grid centre, normal and area, the skin model shape, the analyzer's
// copies), time by 14-21 us per cell on the shared two-core build machine; 10 us is taken, an
// upper estimate on a quiet core. Depth tables add 12 doubles per row and 16 B per vertex.
constexpr double kBytesPerCell = 160.0;
constexpr double kBytesPerDepthStep = 96.0;
constexpr double kBytesPerTableVertex = 16.0;
constexpr double kSecondsPerCell = 1e-5;
constexpr double kSecondsPerTableVertex = 5e-8;

// The cost of `shapes` and the depth tables, without the law's own estimate; `vertices` receives
// the depth tables' vertices.
SceneCost GridCost(const GridShape shapes[2], const PartSpec& inner, const PartSpec& outer,
                   const ModelSettings& model, const RunSettings& run, double* vertices) {
  SceneCost cost;
  cost.inner_cells = shapes[0].cells();
  cost.outer_cells = shapes[1].cells();
  const double cells = static_cast<double>(cost.inner_cells + cost.outer_cells);
  const double columns = std::max(shapes[0].columns, shapes[1].columns);
  const double li = inner.geometry->mating_length(), lo = outer.geometry->mating_length();
  if (model.depth_step > 0.0) {
    cost.depth_steps = std::ceil((li + lo) / model.depth_step);
  } else if (shapes[0].rows > 0 && shapes[1].rows > 0 && li > 0.0 && lo > 0.0) {
    // Auto: one step per shortest row.
    cost.depth_steps = std::ceil((li + lo) / std::min(li / shapes[0].rows, lo / shapes[1].rows));
  }
  *vertices = cost.depth_steps * (columns + 4.0);
  cost.prepare_bytes = cells * kBytesPerCell + cost.depth_steps * kBytesPerDepthStep +
                       *vertices * kBytesPerTableVertex;
  cost.prepare_seconds = cells * kSecondsPerCell + *vertices * kSecondsPerTableVertex;
  const double ticks = std::round(run.duration * run.rate);
  cost.run_bytes = ticks * kStreamBytesPerTick;
  cost.trace_rows = run.write_trace ? ticks : 0.0;
  cost.recording_rows = run.write_recording ? ticks : 0.0;
  cost.output_bytes =
      cost.trace_rows * kTraceFileBytesPerTick + cost.recording_rows * kRecordingFileBytesPerTick;
  return cost;
}

SceneCost CheckPrepare(const ConfigNode& model_node, const ConfigNode& duration,
                       const SurfaceType& surface, const PartSpec& inner, const PartSpec& outer,
                       const ModelSettings& model, const RunSettings& run,
                       const LoadOptions& options) {
  const std::optional<ConfigNode> resolution_node = model_node.Find("resolution");
  const ConfigNode& grid_key = resolution_node ? *resolution_node : model_node;
  const std::unique_ptr<Discretizer> discretizer = surface.MakeDiscretizer();
  GridShape shapes[2];
  const PartSpec* parts[2] = {&inner, &outer};
  for (int k = 0; k < 2; ++k) {
    // A surface type without a discretizer (a test double) takes the resolution as given.
    shapes[k] = discretizer == nullptr
                    ? GridShape{model.resolution.rows, model.resolution.columns}
                    : Located(grid_key, "a resolution the surface type can discretize",
                              [&] { return discretizer->Shape(*parts[k], model.resolution); });
  }
  double vertices = 0.0;
  SceneCost cost = GridCost(shapes, inner, outer, model, run, &vertices);
  const double li = inner.geometry->mating_length(), lo = outer.geometry->mating_length();
  const double columns = std::max(shapes[0].columns, shapes[1].columns);
  const std::optional<ConfigNode> step_node = model_node.Find("depth_step");
  if (step_node && model.depth_step > 0.0 &&
      (!(cost.depth_steps < kMaxDepthSteps) || !(vertices < kMaxDepthTableVertices))) {
    step_node->Fail("a step giving fewer than " + ThreeDigits(kMaxDepthSteps) +
                        " depth-table rows and " + ThreeDigits(kMaxDepthTableVertices) +
                        " table vertices over the " + ThreeDigits(li + lo) + " m stroke",
                    step_node->Describe() + ": " + ThreeDigits(cost.depth_steps) +
                        " rows of up to " + ThreeDigits(columns + 4.0) + " vertices");
  }
  cost.law_prepare_seconds = Located(grid_key, "a grid the law can estimate", [&] {
    return surface.EstimatePrepareSeconds(model, shapes[0], shapes[1], cost.depth_steps);
  });
  cost.prepare_seconds += cost.law_prepare_seconds;
  if (!options.allow_large) {
    SceneCost admitted = cost;
    if (!options.writes_outputs) admitted.output_bytes = 0.0;
    if (const std::optional<CostRefusal> refusal = LargeCostRefusal(admitted)) {
      // The table is the cost when the step is finer than the rows; otherwise the grid is. The
      // outputs are the duration's.
      const double cells = static_cast<double>(cost.inner_cells + cost.outer_cells);
      const bool table = step_node && model.depth_step > 0.0 &&
                         vertices * kSecondsPerTableVertex > cells * kSecondsPerCell;
      const ConfigNode key = refusal->output ? duration : table ? *step_node : grid_key;
      key.Fail(refusal->expected, key.Describe() + ": " + refusal->found);
    }
  }
  // A measured part is resampled onto a cylinder's grid only: refused now, at its key, for a
  // surface whose grid is another (after the cost admission: the grid is built to be checked).
  for (int k = 0; k < 2; ++k) {
    const MeasuredSurface* m = parts[k]->measured.get();
    if (m == nullptr || discretizer == nullptr) continue;
    const SurfaceGrid grid = discretizer->Discretize(*parts[k], model.resolution);
    if (!IsCylinderGrid(grid, parts[k]->size.nominal / 2.0)) {
      throw ScenarioError(m->key_location, m->key_path,
                          "a part of a cylindrical mating surface (measurements are resampled "
                          "onto a cylinder's grid)",
                          "a measured part of a surface whose grid is not a cylinder's");
    }
  }
  return cost;
}

}  // namespace scenario

namespace {

using namespace scenario;

}  // namespace

Scene LoadScene(const std::filesystem::path& file, const PluginRegistry& registry,
                const LoadOptions& options) {
  return LoadSceneFrom(scenario::LoadYamlFile(file), file, registry, options);
}

Scene LoadSceneFromYaml(std::string_view text, const std::filesystem::path& name,
                        const PluginRegistry& registry, const LoadOptions& options) {
  const ConfigNode root = ConfigNode::Parse(NormalizeLineEndings(std::string(text)), name.string());
  if (!root.is_map()) {
    root.Fail("a map of scenario keys (scenario, surface, parts, moving, model, device, run)",
              root.is_null() ? "an empty text" : root.Describe());
  }
  return LoadSceneFrom(root, name, registry, options);
}

namespace scenario {

Scene LoadSceneFrom(const ConfigNode& root, const std::filesystem::path& file,
                    const PluginRegistry& registry, const LoadOptions& options,
                    const RunSettings* step_run) {
  // A part that names a CAD feature becomes a part like any other before anything reads it.
  ResolveCadParts(root, file);
  if (step_run != nullptr) {
    root.ExpectOnlyKeys({"step", "description", "surface", "parts", "moving", "features",
                         "part_motion", "model", "device", "safety", "duration", "seated"});
  } else {
    if (root.Has("steps")) {
      root.Child("steps").Fail(
          "a scenario of one assembly step here (`fitfeel run` and `fitfeel validate` take a "
          "sequence of steps)",
          "a sequence of steps");
    }
    root.ExpectOnlyKeys({"scenario", "description", "surface", "parts", "moving", "features",
                         "part_motion", "model", "device", "safety", "run"});
  }
  const char* const name_key = step_run != nullptr ? "step" : "scenario";
  const char* const run_key = step_run != nullptr ? "duration" : "run";
  // A scene joins its two parts over one mating feature (surface, parts) or several (features).
  const bool several = root.Has("features");
  if (several) {
    for (const char* key : {"surface", "parts"}) {
      if (root.Has(key)) {
        root.Child(key).Fail("no `" + std::string(key) +
                                 "` beside `features` (each feature names its surface and parts)",
                             "both");
      }
    }
  }
  // Every required section is present before any is interpreted, so a missing one is reported
  // first rather than after an unrelated plugin error.
  for (const char* key : {name_key, "moving", "device", run_key}) root.Child(key);
  if (!several) {
    for (const char* key : {"surface", "parts", "model"}) root.Child(key);
  }

  Scene scene;
  scene.file = file;
  const ConfigNode name = root.Child(name_key);
  scene.name = name.AsString();
  if (!IsPlainName(scene.name)) {
    name.Fail(std::string("a ") + name_key +
                  " name of letters, digits, '_', '-' or '.' (it names outputs)",
              name.Describe());
  }
  scene.description = root.StringOr("description", "");
  if (std::optional<ConfigNode> motion = root.Find("part_motion")) {
    scene.part_motion = ParsePartMotion(*motion);
    if (!several && scene.part_motion.rotation == RotationMotion::kFree) {
      motion->Child("rotation")
          .Fail(
              "rotation: free only in a several-feature scene (features), whose flanks can stop it",
              "a one-feature scene");
    }
  }
  if (!several) {
    scene.surface = ResolveSurface(root.Child("surface"), registry, options, &scene.surface_id);
    Parts parts =
        ParseParts(root.Child("parts"), root.Child("moving"), *scene.surface, scene.surface_id);
    scene.moving = parts.moving;
    scene.model = ParseModel(root.Child("model"), *scene.surface, scene.surface_id, parts);
    scene.inner = std::move(parts.inner);
    scene.outer = std::move(parts.outer);
  }
  // A wrench and an axial load act on a screw: elsewhere the device holds the part's twist and
  // depth.
  const bool screw =
      !several && scene.inner.geometry != nullptr && scene.inner.geometry->lead() > 0.0;
  if (std::optional<ConfigNode> motion = root.Find("part_motion"); motion && !screw) {
    for (const char* key : {"turn", "axial_load", "tilt", "grip_lever"}) {
      if (motion->Has(key)) {
        motion->Child(key).Fail(
            "`" + std::string(key) + "` only in a screw scene (a thread's surface)",
            "a scene whose parts slide or turn without advancing");
      }
    }
  }

  const ConfigNode device = root.Child("device");
  if (!device.is_map()) {
    device.Fail("a map with the key plugin and the device plugin's own keys", device.Describe());
  }
  const ConfigNode plugin = device.Child("plugin");
  scene.device_id = plugin.AsString();
  try {
    scene.device = registry.MakeDevice(scene.device_id);
  } catch (const PluginError& e) {
    plugin.Fail(
        "a loaded device plugin id (" + JoinList(LoadedIds(registry, kFitfeelDevicePlugin)) + ")",
        plugin.Describe() + " (" + e.what() + ")");
  }
  if (scene.device == nullptr) throw std::logic_error("plugin registry returned no device object");
  Located(device, "a device configuration the plugin accepts",
          [&] { scene.device->Configure(device); });

  if (std::optional<ConfigNode> safety = root.Find("safety")) {
    if (!safety->is_map()) safety->Fail("a map of safety settings", safety->Describe());
    safety->Keys();  // no repeated keys
    // Parsed here, once: `validate` refuses what `run` would, located, and the run takes the
    // settings as they are.
    scene.safety = ParseSafetySection(*safety);
  }
  const ConfigNode duration =
      step_run != nullptr ? root.Child("duration") : root.Child("run").Child("duration");
  if (step_run != nullptr) {
    scene.run = *step_run;
    scene.run.duration = ParseDuration(duration);
    CheckTicks(duration, scene.run);
  } else {
    scene.run = ParseRun(root.Child("run"), /*sequence=*/false);
  }
  if (several) {
    ParseFeatures(root, duration, registry, options, &scene);
  } else {
    scene.cost = CheckPrepare(root.Child("model"), duration, *scene.surface, scene.inner,
                              scene.outer, scene.model, scene.run, options);
  }
  return scene;
}

}  // namespace scenario

SceneCost EstimateSceneCost(const Scene& scene) {
  if (scene.surface == nullptr || scene.inner.geometry == nullptr ||
      scene.outer.geometry == nullptr) {
    throw std::invalid_argument("EstimateSceneCost: the scene has no surface type or geometry");
  }
  const std::unique_ptr<Discretizer> discretizer = scene.surface->MakeDiscretizer();
  GridShape shapes[2];
  const PartSpec* parts[2] = {&scene.inner, &scene.outer};
  for (int k = 0; k < 2; ++k) {
    shapes[k] = discretizer == nullptr
                    ? GridShape{scene.model.resolution.rows, scene.model.resolution.columns}
                    : discretizer->Shape(*parts[k], scene.model.resolution);
  }
  double vertices = 0.0;
  SceneCost cost = GridCost(shapes, scene.inner, scene.outer, scene.model, scene.run, &vertices);
  cost.law_prepare_seconds =
      scene.surface->EstimatePrepareSeconds(scene.model, shapes[0], shapes[1], cost.depth_steps);
  cost.prepare_seconds += cost.law_prepare_seconds;
  return cost;
}

std::optional<CostRefusal> LargeCostRefusal(const SceneCost& cost) {
  if (cost.prepare_bytes > kLargeSceneBytes || cost.prepare_seconds > kLargeSceneSeconds) {
    const double cells = static_cast<double>(cost.inner_cells + cost.outer_cells);
    return CostRefusal{
        "a scene that prepares within " + ThreeDigits(kLargeSceneBytes / (1 << 30)) + " GiB and " +
            ThreeDigits(kLargeSceneSeconds) + " s, or --allow-large to run it anyway",
        ThreeDigits(cells) + " cells, " + ThreeDigits(cost.depth_steps) + " depth steps, about " +
            ThreeDigits(cost.prepare_bytes / (1 << 20)) + " MiB and " +
            ThreeDigits(cost.prepare_seconds) + " s to prepare" +
            (cost.law_prepare_seconds > 0.0 ? " (" + ThreeDigits(cost.law_prepare_seconds) +
                                                  " s of it the law's own, at worst)"
                                            : std::string()),
        false};
  }
  if (cost.output_bytes > kLargeOutputBytes) {
    return CostRefusal{"a run whose trace.csv and recording.csv stay within " +
                           ThreeDigits(kLargeOutputBytes / (1 << 30)) +
                           " GiB, or --allow-large to write them anyway",
                       ThreeDigits(cost.output_bytes / (1 << 30)) + " GiB of output (" +
                           DescribeOutputs(cost) + ")",
                       true};
  }
  return std::nullopt;
}

std::string DescribeOutputs(const SceneCost& cost) {
  if (cost.output_bytes <= 0.0) return "no trace or recording";
  std::string out;
  if (cost.trace_rows > 0.0) {
    out += ThreeDigits(cost.trace_rows) + " trace rows of about " +
           ThreeDigits(kTraceFileBytesPerTick) + " B";
  }
  if (cost.recording_rows > 0.0) {
    out += std::string(out.empty() ? "" : ", ") + ThreeDigits(cost.recording_rows) +
           " recording rows of about " + ThreeDigits(kRecordingFileBytesPerTick) + " B";
  }
  return out;
}

}  // namespace fitfeel
