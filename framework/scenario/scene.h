#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/device/device.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"
#include "framework/model/surface_type.h"

namespace fitfeel {

class PluginRegistry;

enum class ClockMode { kVirtual, kRealTime };

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
  ModelSettings model;
  std::string device_id;
  std::shared_ptr<Device> device;
  std::optional<ConfigNode> safety;  // the `safety` section when present (force scaling etc.)
  RunSettings run;
};

struct LoadOptions {
  // Accept a surface type that renders no forces (the thread stub), for inspecting its skin model
  // shapes and for the conformance suite; `fitfeel run` never sets it.
  bool allow_non_rendering = false;
};

// Parses, validates and resolves plugins for one scenario file. Throws ScenarioError
// (file:line:column, key path, expected, found) for any problem, before anything runs.
FITFEEL_API Scene LoadScene(const std::filesystem::path& file, const PluginRegistry& registry,
                            const LoadOptions& options = {});

}  // namespace fitfeel
