// The seven ISO 286 fits at 20 mm on a Touch through the perceptual force mapping
// (framework/safety/force_mapping.h): the shipped scenes, the simulated robot rendering as a Touch
// (`model: touch, force_mapping: perceptual`), same seed. Their scene forces span 0.3 N (a
// clearance fit's friction) to 14 kN (H7/s6); a Touch gives 1.1 N for a thermal window. The
// mapping keeps every fit apart by more than the 7 % a hand tells apart (Pang, Tan & Durlach
// 1991), keeps equal scene forces equal, and neither the thermal model nor the peak rating cuts a
// tick.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// The shipped scene with its device rendering as a Touch through the perceptual mapping.
fs::path OnATouch(const std::string& fit, const fs::path& dir) {
  const std::string name = "fits-20mm-h7" + fit + ".yaml";
  std::string text = test_support::ReadText(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / name);
  const std::string plugin = "  plugin: fitfeel.device.simulated\n";
  const std::size_t at = text.find(plugin);
  if (at == std::string::npos) throw std::runtime_error(name + ": no simulated device section");
  text.insert(at + plugin.size(), "  model: touch\n  force_mapping: perceptual\n");
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

struct FitRun {
  std::string fit;
  double scene_mean = 0.0;      // axial_resistance_N mean
  double delivered_mean = 0.0;  // delivered_force_N mean
};

TEST(PerceptualMapping, SevenFitsOnATouchStayApartAndWithinTheRatings) {
  const fs::path dir = test_support::EmptyFolder("perceptual-mapping", "fits-20mm");
  std::vector<FitRun> runs;
  for (const std::string fit : {"g6", "h6", "js6", "k6", "n6", "p6", "s6"}) {
    SCOPED_TRACE(fit);
    Scene scene = LoadScene(OnATouch(fit, dir), test_support::BuildTreePlugins());
    const RunResult result = RunScene(std::move(scene), RunOptions{});
    const nlohmann::json& s = result.summary;
    const nlohmann::json& safety = s["safety"];
    ASSERT_EQ(safety["force_mapping"]["kind"], "perceptual");
    EXPECT_NEAR(safety["force_mapping"]["device_top_N"].get<double>(), 1.107, 1e-3);
    // (c) Within the Touch's ratings throughout: the map spends no more than one thermal window.
    EXPECT_EQ(safety["continuous_limited_ticks"].get<std::uint64_t>(), 0u);
    EXPECT_EQ(safety["peak_limited_ticks"].get<std::uint64_t>(), 0u);
    EXPECT_EQ(safety["faults"].get<std::uint64_t>(), 0u);
    // (d) The map's slope is at most 1: the rendering stays passive.
    EXPECT_LE(safety["energy_created_J"].get<double>(), 1e-9);
    ASSERT_TRUE(s["axial_resistance_N"].is_object());
    runs.push_back({fit, s["axial_resistance_N"]["mean"].get<double>(),
                    s["delivered_force_N"]["mean"].get<double>()});
  }
  std::string table;
  for (const FitRun& r : runs) {
    char line[160];
    std::snprintf(line, sizeof line, "H7/%-3s scene %10.4f N  delivered %.4f N\n", r.fit.c_str(),
                  r.scene_mean, r.delivered_mean);
    table += line;
    RecordProperty("delivered_mean_N_" + r.fit, std::to_string(r.delivered_mean));
  }
  std::printf("perceptual mapping on a Touch, mean forces:\n%s", table.c_str());

  // (b) The clearance fits draw equal scene forces with seed 1 (their only resistance is the
  // friction of the part's weight): they stay equal on the device, and are felt.
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(runs[i].delivered_mean, runs[0].delivered_mean, 1e-3 * runs[0].delivered_mean)
        << runs[i].fit;
    EXPECT_GE(runs[i].delivered_mean, 0.1) << runs[i].fit;
  }
  // (a) js6 < k6 < n6 < p6 < s6 on the device, each step at least a Weber fraction (7 %).
  for (int i = 3; i < 7; ++i) {
    EXPECT_GE(runs[i].delivered_mean, 1.07 * runs[i - 1].delivered_mean)
        << runs[i - 1].fit << " -> " << runs[i].fit << "\n"
        << table;
  }
}

}  // namespace
}  // namespace fitfeel
