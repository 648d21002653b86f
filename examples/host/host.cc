// A host program built against the installed package: loads a scene through the plugin registry
// (FITFEEL_PLUGIN_PATH, then the installed plugins), runs it in virtual time and reports what the
// summary says. Usage: fitfeel_example_host SCENARIO OUT_DIR
#include <cstdio>
#include <exception>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SCENARIO OUT_DIR\n", argv[0]);
    return 2;
  }
  try {
    fitfeel::PluginRegistry registry;
    registry.LoadAll();
    fitfeel::Scene scene = fitfeel::LoadScene(argv[1], registry);
    fitfeel::RunOptions options;
    options.out_dir = argv[2];
    options.clock = fitfeel::ClockMode::kVirtual;
    const fitfeel::RunResult result = fitfeel::RunScene(std::move(scene), options);
    std::printf("%s: %llu ticks, peak axial resistance %.3f N\n", argv[1],
                static_cast<unsigned long long>(result.stats.ticks),
                result.summary["axial_resistance_N"]["max"].get<double>());
    return 0;
  } catch (const fitfeel::ScenarioError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fitfeel_example_host: %s\n", e.what());
    return 1;
  }
}
