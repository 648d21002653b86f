// fitfeel stability: where rendering methods fail. Sweeps the contact stiffness (x rate x virtual
// damping) of a sampled wall against a simulated hand, rendered directly and through the safety
// chain's virtual coupling, around the passivity bound and at the scene's own press-fit
// stiffness, and writes the stability map as CSV and, asked for, as a chart
// (framework/stability/README.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/cli/interrupts.h"
#include "framework/cli/strict_options.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/quantity.h"
#include "framework/device/device_specs.h"
#include "framework/plot/gnuplot.h"
#include "framework/plugin/registry.h"
#include "framework/safety/safety_settings.h"
#include "framework/safety/virtual_coupling.h"
#include "framework/scenario/scene.h"
#include "framework/stability/stability_chart.h"
#include "framework/stability/stability_map.h"
#include "framework/stability/stiction_experiment.h"

namespace fitfeel::cli {
namespace {

struct StabilityOptions {
  std::string scenario = kDefaultScenario;
  std::string device;
  std::string output;
  std::vector<std::string> rates;
  std::vector<std::string> dampings;
  std::string stiffness_min = "100 N/m";
  std::string stiffness_max = "100 N/mm";
  int per_decade = 8;
  std::string hand_mass;
  std::string push;
  std::string horizon;
  std::optional<double> force_scale;
};

double Quantity(const std::string& option, const std::string& text, Dimension dimension) {
  try {
    return ParseQuantity(text, dimension);
  } catch (const std::invalid_argument& e) {
    throw UserError("stability: " + option + " '" + text + "': " + e.what());
  }
}

std::string Number(double value, const char* format = "%.4g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// The device whose limits and damping the sweep uses: --device, else the scene's device when it
// is one of the known models (with the scene's overrides), else the PHANTOM Desktop.
DeviceSpec ChooseDevice(const StabilityOptions& options, const Scene& scene) {
  if (!options.device.empty()) return LookupDeviceSpec(options.device);
  if (scene.device) {
    const DeviceSpec spec = scene.device->spec();
    if (FindDeviceSpec(spec.model)) return spec;
  }
  return LookupDeviceSpec("PHANTOM Desktop");
}

double ForceScale(const StabilityOptions& options, const Scene& scene, const DeviceSpec& spec) {
  if (options.force_scale) {
    if (!(*options.force_scale > 0.0) || !std::isfinite(*options.force_scale)) {
      throw UserError("stability: --force-scale must be a positive number");
    }
    return *options.force_scale;
  }
  if (!scene.safety) return 1.0;
  const SafetySettings& safety = scene.safety->settings;
  if (safety.physical_full_scale) return spec.max_continuous_force / *safety.physical_full_scale;
  return safety.force_scale;
}

void Run(const StabilityOptions& options) {
  // The sweep writes nothing: until the map is written, SIGINT or SIGTERM ends the process at once;
  // then the write completes.
  InterruptScope interrupt("fitfeel stability");
  // Every input is checked before anything runs or is written.
  PluginRegistry registry;
  registry.LoadAll();
  // The sweep takes the scene's device, safety and stiffness; its grid is never prepared and no
  // run output written, so neither cost is admitted.
  LoadOptions load;
  load.allow_large = true;
  load.writes_outputs = false;
  const Scene scene = LoadScene(options.scenario, registry, load);
  const DeviceSpec spec = ChooseDevice(options, scene);
  ValidateDeviceSpec(spec);
  const double scale = ForceScale(options, scene, spec);
  const double kp = scene.model.contact_stiffness;
  if (!(kp > 0.0)) {
    throw UserError("stability: scenario '" + scene.file.string() +
                    "' leaves model.contact_stiffness to the surface type (auto); give it in the "
                    "scenario to sweep against it");
  }

  StabilityMapSettings map;
  WallExperiment& base = map.base;
  base.spec = spec;
  base.force_scale = scale;
  if (!options.hand_mass.empty()) {
    base.hand_mass = Quantity("--hand-mass", options.hand_mass, Dimension::kMass);
  }
  if (!options.push.empty()) base.push_force = Quantity("--push", options.push, Dimension::kForce);
  if (!options.horizon.empty()) {
    base.horizon = Quantity("--horizon", options.horizon, Dimension::kTime);
  }
  if (!(base.hand_mass > 0.0)) throw UserError("stability: --hand-mass must be positive");
  if (!(base.push_force > 0.0) || !(base.push_force < spec.max_continuous_force)) {
    throw UserError(
        "stability: --push must be above 0 N and below the device's continuous rating (" +
        Number(spec.max_continuous_force) + " N)");
  }
  if (!(base.horizon > 0.0) || base.horizon > 60.0) {
    throw UserError("stability: --horizon must be in (0, 60] s");
  }

  if (options.rates.empty()) {
    map.rates = {250.0, 500.0, 1000.0, 2000.0};
  } else {
    for (const std::string& r : options.rates) {
      map.rates.push_back(Quantity("--rate", r, Dimension::kFrequency));
    }
  }
  if (std::find(map.rates.begin(), map.rates.end(), scene.run.rate) == map.rates.end()) {
    map.rates.push_back(scene.run.rate);
  }
  std::sort(map.rates.begin(), map.rates.end());
  for (double r : map.rates) {
    if (!(r >= 10.0 && r <= 100e3)) throw UserError("stability: a rate must be in 10 Hz..100 kHz");
  }
  // Virtual damping: none, and a fifth of the device's damping either way (enough to move the
  // bound visibly, small enough to leave room for K).
  if (options.dampings.empty()) {
    map.dampings = {-0.2 * spec.damping, 0.0, 0.2 * spec.damping};
  } else {
    for (const std::string& d : options.dampings) {
      map.dampings.push_back(Quantity("--damping", d, Dimension::kDamping));
    }
  }
  const double k_min = Quantity("--stiffness-min", options.stiffness_min, Dimension::kStiffness);
  const double k_max = Quantity("--stiffness-max", options.stiffness_max, Dimension::kStiffness);
  if (!(k_min > 0.0) || !(k_max >= k_min)) {
    throw UserError("stability: need 0 < --stiffness-min <= --stiffness-max");
  }
  map.stiffnesses = LogSpaced(k_min, k_max, options.per_decade);
  // The case's own stiffnesses at the device: k_p, and the Lame normal stiffness of a joint in
  // all-round contact (p' pi d1 L, twice the radial k_p = p' pi d1 L / 2 of eq. 9).
  const double case_kp = scale * kp;
  const double case_lame = 2.0 * case_kp;
  map.stiffnesses.push_back(case_kp);
  map.stiffnesses.push_back(case_lame);
  std::sort(map.stiffnesses.begin(), map.stiffnesses.end());

  // -o FILE.png or FILE.svg: the chart there and its data beside it as FILE.csv.
  const std::filesystem::path output = options.output;
  const bool chart = output.extension() == ".png" || output.extension() == ".svg";
  std::vector<plot::OutputFile> images;
  if (chart) {
    images = plot::ResolveOutputs(output);
    plot::Gnuplot::Find();  // UnsupportedError now rather than after the sweep
  }
  const std::string path =
      options.output.empty()
          ? scene.name + "-stability.csv"
          : (chart ? std::filesystem::path(output).replace_extension(".csv") : output).string();
  CheckOutputFile("--output", path);
  if (chart) CheckOutputFile("--output", output);

  const std::vector<StabilityMapRow> rows = SweepStabilityMap(map);
  interrupt.Cooperate();
  SweepStaleTemporaries(std::filesystem::path(path).parent_path());
  WriteFileAtomically(path, StabilityMapCsv(rows));
  if (chart) {
    RenderStabilityMap(
        rows, spec.damping,
        "Stability of " + spec.model + " against " + scene.name + ": direct and coupled rendering",
        images);
  }

  const double b = spec.damping;
  std::cout << "stability of " << spec.model << " (b = " << Number(b) << " N*s/m, peak "
            << Number(spec.max_force) << " N, continuous " << Number(spec.max_continuous_force)
            << " N) against " << scene.name << "\n";
  std::cout << "contact stiffness k_p = " << Number(kp) << " N/m, force scale " << Number(scale)
            << " device N per physical N: " << Number(case_kp) << " N/m at the device (Lame "
            << Number(case_lame) << " N/m); hand " << Number(base.hand_mass) << " kg pushed with "
            << Number(base.push_force) << " N, " << Number(base.horizon) << " s per run\n\n";
  std::cout << "direct rendering: passivity bound K = 2 (b - |B|) / T against the measured "
               "boundary\n";
  std::cout << "  rate_Hz  B_Ns/m   bound_N/m  measured_N/m  ratio\n";
  for (double rate : map.rates) {
    for (double damping : map.dampings) {
      const double bound = 2.0 * (b - std::abs(damping)) * rate;
      std::string measured = "n/a", ratio = "";
      if (bound > 0.0) {
        WallExperiment e = base;
        e.method = RenderingMethod::kDirect;
        e.rate = rate;
        e.damping = damping;
        // Above the bound for B <= 0; for B > 0 the hand-as-mass boundary is the low-frequency
        // one, 2 (b + B) / T, which the bracket must contain.
        const double high = 4.0 * 2.0 * (b + std::abs(damping)) * rate;
        try {
          const double k = MeasureStabilityBoundary(e, 0.25 * bound, high);
          measured = Number(k, "%.5g");
          ratio = Number(k / bound, "%.3f");
        } catch (const UserError&) {
          measured = "none";
        }
      }
      std::printf("  %7g  %6.3g  %10.5g  %12s  %5s\n", rate, damping, bound > 0.0 ? bound : 0.0,
                  measured.c_str(), ratio.c_str());
    }
  }
  std::cout << "\nat the case's stiffness:\n";
  std::cout
      << "  method   rate_Hz  B_Ns/m  K_N/m       K_c_N/m  B_c_Ns/m  stable  energy_growth_J  "
         "peak_force_N\n";
  for (const StabilityMapRow& r : rows) {
    if (r.stiffness != case_kp && r.stiffness != case_lame) continue;
    const CouplingGains gains = r.method == RenderingMethod::kCoupled
                                    ? DefaultCouplingGains(spec, 1.0 / r.rate)
                                    : CouplingGains{};
    std::printf("  %-7s  %7g  %6.3g  %-10.4g  %7.4g  %8.4g  %-6s  %15.4g  %12.4g\n",
                ToString(r.method).c_str(), r.rate, r.damping, r.stiffness, gains.stiffness,
                gains.damping, r.outcome.stable ? "yes" : "no", r.outcome.energy_growth,
                r.outcome.peak_force);
  }
  // Stiction (docs/friction.md): the scene's stick-slip friction under a normal force whose
  // breakaway is 1.5 pushes at the device, held (push) and broken (the breakaway plus a third of
  // the way to the continuous rating), direct and coupled, at the scene's rate.
  const FrictionParameters friction = FrictionOf(scene.model);
  if (friction.static_coefficient > 0.0) {
    const double breakaway = std::min(1.5 * base.push_force, 0.9 * spec.max_continuous_force);
    const double hold = breakaway / 1.5;
    const double slide = breakaway + (spec.max_continuous_force - breakaway) / 3.0;
    StictionExperiment e;
    e.spec = spec;
    e.rate = scene.run.rate;
    e.force_scale = scale;
    e.friction = friction;
    e.normal_force = breakaway / (scale * friction.static_coefficient);
    e.hand_mass = base.hand_mass;
    e.horizon = base.horizon;
    std::cout << "\nstiction: mu_s " << Number(friction.static_coefficient) << ", mu_k "
              << Number(friction.kinetic_coefficient) << ", breakaway displacement "
              << Number(friction.breakaway_displacement * 1e6) << " um, normal force "
              << Number(e.normal_force) << " N: breakaway " << Number(breakaway)
              << " N at the device\n";
    std::cout << "  method   push_N  sliding  displacement_mm  final_speed_mm_s  contact_work_J  "
                 "stable\n";
    for (RenderingMethod method : {RenderingMethod::kDirect, RenderingMethod::kCoupled}) {
      for (double push : {hold, slide}) {
        e.method = method;
        e.push_force = push;
        const StictionOutcome out = RunStictionExperiment(e);
        std::printf("  %-7s  %6.3g  %-7s  %15.4g  %16.4g  %14.4g  %s\n", ToString(method).c_str(),
                    push, out.sliding ? "yes" : "no", out.displacement * 1e3, out.final_speed * 1e3,
                    out.contact_work, push == hold ? (out.stable ? "yes" : "no") : "-");
      }
    }
  }

  std::size_t stable = 0;
  for (const StabilityMapRow& r : rows) stable += r.outcome.stable ? 1 : 0;
  std::cout << "\nstability map: " << rows.size() << " runs (" << stable << " stable) -> " << path
            << (chart ? ", " + output.string() : std::string()) << "\n";
}

}  // namespace

void AddStabilityCommand(CLI::App& app) {
  auto options = std::make_shared<StabilityOptions>();
  auto* cmd = app.add_subcommand(
      "stability",
      "Sweep contact stiffness x rate x virtual damping for direct and coupled rendering of the "
      "scene's contact against a simulated hand, and write the stability map (CSV, and a chart "
      "for -o FILE.png or FILE.svg)");
  cmd->add_option("scenario", options->scenario, "Scenario file")->default_str(kDefaultScenario);
  cmd->add_option("--device", options->device,
                  "Device model whose limits and damping are used (default: the scene's device "
                  "when it is a known model, else PHANTOM Desktop)");
  cmd->add_option("-o,--output", options->output,
                  "CSV file to write (default: <scenario name>-stability.csv); FILE.png or "
                  "FILE.svg draws the map there (a panel per damping) and writes FILE.csv");
  cmd->add_option("--rate", options->rates,
                  "Rendering rate, repeatable (default 250 Hz, 500 Hz, "
                  "1 kHz, 2 kHz and the scene's rate)")
      ->delimiter(',');
  cmd->add_option("--damping", options->dampings,
                  "Virtual damping B at the device, repeatable (default -b/5, 0, b/5)")
      ->delimiter(',');
  cmd->add_option("--stiffness-min", options->stiffness_min, "Low end of the stiffness sweep")
      ->default_str("100 N/m");
  cmd->add_option("--stiffness-max", options->stiffness_max, "High end of the stiffness sweep")
      ->default_str("100 N/mm");
  AddIntegerOption(
      cmd, "--per-decade", 1, 100, [options](long n) { options->per_decade = static_cast<int>(n); },
      "Stiffness values per decade (default 8)");
  cmd->add_option("--hand-mass", options->hand_mass, "Mass of the simulated hand (default 0.2 kg)");
  cmd->add_option("--push", options->push, "Steady push of the hand (default 0.5 N)");
  cmd->add_option("--horizon", options->horizon, "Simulated time per run (default 2 s)");
  AddQuantityOption(
      cmd, "--force-scale", Dimension::kDimensionless, 1e-6, 1e6,
      [options](double scale) { options->force_scale = scale; },
      "Device N per physical N (default: the scene's safety section, else 1)");
  cmd->callback([options] { Run(*options); });
}

}  // namespace fitfeel::cli
