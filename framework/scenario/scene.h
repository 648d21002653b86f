#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/device/device.h"
#include "framework/model/gps_spec.h"
#include "framework/model/joint_features.h"
#include "framework/model/model_settings.h"
#include "framework/model/surface_type.h"
#include "framework/safety/safety_settings.h"
#include "framework/scenario/part_motion_settings.h"

namespace fitfeel {

class PluginRegistry;

enum class ClockMode { kVirtual, kRealTime };

// What a run holds in memory per tick. A run streams its trace and recording to disk (RunScene,
// TraceStream) and keeps per tick only its compute time and, in real time, three timing stamps:
// kStreamBytesPerTick. A caller that keeps the trace in memory (Scheduler without a stream: tests,
// benchmarks) holds the record and those stamps, and the device sample when it records. The
// scheduler checks at compile time that its records fit these, so the loader's refusal and the
// scheduler's agree.
inline constexpr double kStreamBytesPerTick = 32.0;
inline constexpr double kTraceBytesPerTick = 768.0;
inline constexpr double kRecordingBytesPerTick = 240.0;
// The buffers of one run: beyond this a scene is refused rather than swapped.
inline constexpr double kMaxRunBufferBytes = 2.0 * 1024 * 1024 * 1024;

// What preparing a scene will cost, estimated from its grid and depth-table sizes before anything
// is allocated (LoadScene). A scene above kLargeSceneBytes or kLargeSceneSeconds is refused
// unless LoadOptions::allow_large.
struct SceneCost {
  long inner_cells = 0, outer_cells = 0;
  double depth_steps = 0.0;     // rows of the contact analyzer's depth tables
  double prepare_bytes = 0.0;   // grids, skin model shapes, analyzer tables
  // On one core of the reference machine: the cells', the tables' and the law's own estimate
  // (SurfaceType::EstimatePrepareSeconds; docs/scenario-format.md).
  double prepare_seconds = 0.0;
  double law_prepare_seconds = 0.0;  // of it, the law's own worst case (0: none of its own)
  double run_bytes = 0.0;       // what the run keeps per tick (kStreamBytesPerTick each)
  // What the run writes: rows of trace.csv and recording.csv (0 when not written), and their
  // bytes estimated at kTraceFileBytesPerTick and kRecordingFileBytesPerTick a row.
  double trace_rows = 0.0;
  double recording_rows = 0.0;
  double output_bytes = 0.0;
};
inline constexpr double kLargeSceneBytes = 1.0 * 1024 * 1024 * 1024;
inline constexpr double kLargeSceneSeconds = 30.0;
// A row of trace.csv and of recording.csv, estimated from the shipped scenes' runs
// (docs/scenario-format.md, "Output size"): shortest decimals make a row's length vary with its
// values; these are above the longest mean measured.
inline constexpr double kTraceFileBytesPerTick = 360.0;
inline constexpr double kRecordingFileBytesPerTick = 300.0;
// The outputs a run writes without --allow-large: an hour at a device's 1 kHz with trace and
// recording (about 2.4 GB) fits; the longest run the scheduler takes, an hour at 10 kHz (13 GB of
// trace), would fill a disk unasked and is more than a spreadsheet or a plotting script reads
// whole. 4 GiB is also the largest file FAT32 media hold.
inline constexpr double kLargeOutputBytes = 4.0 * 1024 * 1024 * 1024;

// Why the loader refuses a cost without --allow-large, as the two halves of its message; `output`
// when the outputs are the excess (refused at run.duration), not the preparation (at
// model.resolution or model.depth_step).
struct CostRefusal {
  std::string expected;  // "a scene that prepares within 1 GiB and 30 s, or --allow-large ..."
  std::string found;     // "8e+06 cells, 40 depth steps, about 1.22e+03 MiB and 80 s to prepare"
  bool output = false;
};
// The refusal of `cost` over kLargeSceneBytes, kLargeSceneSeconds or kLargeOutputBytes (the
// preparation first); nullopt when every threshold holds.
FITFEEL_API std::optional<CostRefusal> LargeCostRefusal(const SceneCost& cost);
// The outputs' rows: "3.6e+06 trace rows of about 400 B, 3.6e+06 recording rows of about 120 B".
FITFEEL_API std::string DescribeOutputs(const SceneCost& cost);

// The scenario's `run` section.
struct RunSettings {
  double rate = 1000.0;    // Hz
  double duration = 0.0;   // s
  std::uint64_t seed = 1;
  ClockMode clock = ClockMode::kVirtual;
  bool write_trace = true;
  bool write_summary = true;
  bool write_recording = false;
};

// Where a mating feature of a several-feature scene lies (docs/assemblies.md). The joint frame is
// the fixed body's: y along the insertion, its origin on the first feature's axis at that
// feature's entrance; both bodies' datums coincide there at nominal. Every feature's axis is
// parallel to y.
struct FeaturePlacement {
  Eigen::Vector2d at{0.0, 0.0};  // (x, z) of the feature's axis in the joint frame, nominal, m
  double angle = 0.0;            // the feature's own frame turned about y from the joint's, rad
  // Insertion of the first feature before this one meets (its entrance or leading end lies that
  // much further back), m; 0 for the first.
  double engages_after = 0.0;
  // ISO 1101 position tolerance of the feature's axis on each body (diameter of the cylindrical
  // zone about its nominal place), m; 0: exact. Drawn once per seed.
  double inner_position = 0.0;
  double outer_position = 0.0;
  // In a sequence: where an earlier step left the part that this feature's fixed side belongs to,
  // across its axis, in the feature's frame (m), added to the fixed side's place; zero otherwise.
  Eigen::Vector2d seat{0.0, 0.0};
};

// One mating feature of a several-feature scene: a surface type with its pair of part sides and
// its own model settings (the scene's `model` unless the feature gives its own).
struct MatingFeature {
  std::string name;
  std::string surface_id;
  std::shared_ptr<const SurfaceType> surface;
  PartSpec inner;
  PartSpec outer;
  Role moving = Role::kInner;  // the side of this feature on the moving body
  ModelSettings model;
  FeaturePlacement placement;
};

// A fully parsed and checked scenario, in SI units. Nothing has run yet: the device is configured
// but not started, and no skin model shape exists.
struct Scene {
  std::filesystem::path file;
  std::string name;
  std::string description;
  std::string surface_id;
  std::shared_ptr<const SurfaceType> surface;
  PartSpec inner;
  PartSpec outer;
  Role moving = Role::kInner;
  PartMotionSettings part_motion;  // the `part_motion` section (absent: quasi-static)
  ModelSettings model;
  std::string device_id;
  std::shared_ptr<Device> device;
  std::optional<SafetySection> safety;  // the `safety` section when present (force scaling etc.)
  RunSettings run;
  SceneCost cost;
  // A several-feature scene (`features`): every feature, the first one also in surface, inner,
  // outer, moving and model above, so that what reads one feature reads the datum feature. Empty
  // for a one-feature scene.
  std::vector<MatingFeature> features;
  std::string fixed_body, moving_body;  // the two bodies' names (several-feature scenes)
};

struct LoadOptions {
  // Accept a surface type that renders no forces (a test double), for inspecting its skin model
  // shapes and for the conformance suite; `fitfeel run` never sets it.
  bool allow_non_rendering = false;
  // Accept a scene whose estimated cost exceeds kLargeSceneBytes or kLargeSceneSeconds, or whose
  // outputs exceed kLargeOutputBytes (`--allow-large`).
  bool allow_large = false;
  // The caller writes the run's trace and recording as the scenario asks (run, validate, the C
  // API): their estimated size is admitted with the cost. A caller that writes neither (sms,
  // plot, study) clears it; SceneCost still holds the estimate.
  bool writes_outputs = true;
};

// Parses, validates and resolves plugins for one scenario file. Throws ScenarioError
// (file:line:column, key path, expected, found) for any problem, before anything runs: this is
// the one checking path, so everything a run could refuse about the scene alone (grid shapes the
// surface cannot discretize, depth tables over their cap, a run shorter than one tick or over
// its buffer cap, a cost above the large-scene thresholds, outputs above the large-output one, a
// plugin's own constraints) is refused here, located at the key that causes it.
FITFEEL_API Scene LoadScene(const std::filesystem::path& file, const PluginRegistry& registry,
                            const LoadOptions& options = {});
// The same from YAML text (an engine's own scene, the C API); `name` stands for the file in
// messages and relative paths (a replay's recording) resolve from the working folder.
FITFEEL_API Scene LoadSceneFromYaml(std::string_view text, const std::filesystem::path& name,
                                    const PluginRegistry& registry,
                                    const LoadOptions& options = {});

// What preparing and running `scene` costs with its settings as they are now: for a command that
// changes a loaded scene's grid or duration (tradeoff's ladder and --duration) and must admit the
// change as the loader admits the scene's own (LargeCostRefusal). Throws UserError for a
// resolution the surface type cannot discretize, std::invalid_argument for a scene without a
// surface type or geometries.
FITFEEL_API SceneCost EstimateSceneCost(const Scene& scene);

}  // namespace fitfeel
