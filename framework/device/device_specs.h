#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/device/device.h"

namespace fitfeel {

// The built-in table of device specs (PHANTOM Desktop, PHANTOM Omni, Touch, PHANTOM Premium 1.0,
// 1.5, 1.5 High Force and 3.0). Limits the safety
// chain relies on are data, not code: a scenario overrides any field (see ParseDeviceSpec).
FITFEEL_API const std::vector<DeviceSpec>& KnownDeviceSpecs();
// Their names, quoted and listed for a message: "'PHANTOM Desktop', 'PHANTOM Omni', ...".
FITFEEL_API std::string KnownDeviceModels();

// Case-, space-, hyphen- and underscore-insensitive lookup by model name or alias
// ("PHANTOM Desktop", "phantom-desktop", "desktop", "Omni", "Geomagic Touch", "touch",
// "premium-1.0", "premium-1.5", "premium-1.5-hf", "Premium 1.5 High Force", "premium-3.0").
FITFEEL_API std::optional<DeviceSpec> FindDeviceSpec(std::string_view model);
// Same, but throws UserError naming the known models when `model` is not one of them.
FITFEEL_API DeviceSpec LookupDeviceSpec(std::string_view model);

// Throws UserError unless every limit is finite and positive and the continuous force does not
// exceed the peak force.
FITFEEL_API void ValidateDeviceSpec(const DeviceSpec& spec);

// Applies a scenario's spec overrides on top of `base`. `node` is a map with any of:
//   model: <name>                    start from that table entry instead of `base`
//   max_force: <force>               max_continuous_force: <force>
//   max_stiffness: <stiffness>       damping: <damping>
//   workspace: [<length>, <length>, <length>]   (x, y, z extents of the reachable box)
//   native_rate: <frequency>
//   force_mapping: linear | perceptual   (framework/safety/force_mapping.h)
// Throws ScenarioError at the offending key (unknown key, bad unit, out of range, continuous force
// above peak force).
FITFEEL_API DeviceSpec ParseDeviceSpec(const ConfigNode& node, const DeviceSpec& base);

}  // namespace fitfeel
