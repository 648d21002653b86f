// A measured part end to end on the real plugins: the paper's drawn pair written as measurement
// files and loaded back as measured parts gives the same run bit for bit; a part outside its
// drawing is rendered and reported as such.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/model/measured_surface.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;
using ::fitfeel::test_support::ReadText;

// trace.csv without its timing column (tick_us, the 7th), the only one not fixed in virtual time.
std::string TraceWithoutTimings(const fs::path& file) {
  std::istringstream in(ReadText(file));
  std::string line, out;
  while (std::getline(in, line)) {
    std::size_t start = 0;
    for (int k = 0; k < 6; ++k) start = line.find(',', start) + 1;
    const std::size_t end = line.find(',', start);
    out += line.substr(0, start) + line.substr(end + 1) + "\n";
  }
  return out;
}

class MeasuredPart : public ::testing::Test {
 protected:
  MeasuredPart()
      : registry_({fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins"}),
        // One folder per test: ctest runs the tests of this file in parallel.
        dir_(fs::temp_directory_path() /
             (std::string("fitfeel_measured_part_") +
              ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    registry_.LoadAll();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~MeasuredPart() override { fs::remove_all(dir_); }

  // The paper scene with both parts measured from `shaft` and `bushing` files in dir_.
  fs::path MeasuredScene() const {
    std::string text = ReadText(paper_);
    auto insert = [&text](const std::string& after, const std::string& line) {
      const std::size_t at = text.find(after);
      ASSERT_NE(at, std::string::npos) << after;
      text.insert(at + after.size(), line);
    };
    insert("\n  shaft:\n", "    measured: {roundness: shaft.csv}\n");
    insert("\n  bushing:\n", "    measured: {roundness: bushing.csv}\n");
    const fs::path file = dir_ / "measured.yaml";
    std::ofstream(file) << text;
    return file;
  }

  RunResult Run(const fs::path& scene_file, const fs::path& out,
                Eigen::VectorXd* inner = nullptr) const {
    RunOptions options;
    options.out_dir = out;
    options.clock = ClockMode::kVirtual;
    options.prepared = [inner](const PreparedScene& p) {
      if (inner != nullptr) *inner = p.inner_sms->variation;
    };
    return RunScene(LoadScene(scene_file, registry_), options);
  }

  const fs::path paper_ = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios/paper-case1-h7js6.yaml";
  PluginRegistry registry_;
  fs::path dir_;
};

TEST_F(MeasuredPart, DrawnPairWrittenAndMeasuredRunsTheSameBitForBit) {
  const Scene drawn = LoadScene(paper_, registry_);
  Rng rng(drawn.run.seed);
  const SkinModelShapes shapes = GenerateSkinModelShapes(drawn, rng);
  std::ofstream(dir_ / "shaft.csv") << MeasurementCsv(shapes.inner, "shaft");
  std::ofstream(dir_ / "bushing.csv") << MeasurementCsv(shapes.outer, "bushing");

  Eigen::VectorXd v_drawn, v_measured;
  const RunResult a = Run(paper_, dir_ / "drawn", &v_drawn);
  const RunResult b = Run(MeasuredScene(), dir_ / "measured", &v_measured);
  ASSERT_EQ(v_drawn.size(), v_measured.size());
  EXPECT_TRUE(v_drawn == v_measured);
  EXPECT_EQ(TraceWithoutTimings(dir_ / "drawn/trace.csv"),
            TraceWithoutTimings(dir_ / "measured/trace.csv"));
  EXPECT_EQ(a.summary["axial_resistance_N"], b.summary["axial_resistance_N"]);
  EXPECT_GT(a.summary["constrained_ticks"].get<int>(), 1000);

  // The summary says where the parts came from and that they meet their drawing.
  EXPECT_FALSE(a.summary.contains("measured_parts"));
  const auto& parts = b.summary.at("measured_parts");
  EXPECT_EQ(parts.at("shaft").at("kind"), "roundness");
  EXPECT_TRUE(parts.at("shaft").at("meets_drawing").get<bool>());
  EXPECT_TRUE(parts.at("bushing").at("meets_drawing").get<bool>());
}

TEST_F(MeasuredPart, OutOfToleranceMeasurementIsRenderedAndReported) {
  // A shaft 30 um over nominal (limits -8/+8 um) with an ovality of 4 um (radial).
  std::string csv = "# synthetic\nangle [deg],height [mm],deviation [um]\n";
  for (double y : {0.5, 20.0, 39.5}) {
    for (int a = 0; a < 360; a += 10) {
      csv += std::to_string(a) + "," + std::to_string(y) + "," +
             std::to_string(15.0 + 2.0 * std::cos(2.0 * a * 3.141592653589793 / 180.0)) + "\n";
    }
  }
  std::ofstream(dir_ / "shaft.csv") << csv;
  Rng rng(1);
  std::ofstream(dir_ / "bushing.csv")
      << MeasurementCsv(GenerateSkinModelShapes(LoadScene(paper_, registry_), rng).outer, "");
  const RunResult r = Run(MeasuredScene(), dir_ / "over");
  const auto& shaft = r.summary.at("measured_parts").at("shaft");
  EXPECT_FALSE(shaft.at("meets_drawing").get<bool>());
  bool size_fails = false;
  for (const auto& c : shaft.at("characteristics")) {
    if (c.at("name") == "two_point_size_max") {
      EXPECT_NEAR(c.at("value_um").get<double>(), 34.0, 0.1);  // 2 * (15 + 2) um on the diameter
      size_fails = !c.at("pass").get<bool>();
    }
  }
  EXPECT_TRUE(size_fails);
  // 30 um over a bore of 0..25 um: an interference fit, tens of newtons at least.
  EXPECT_GT(r.summary.at("interference_ticks").get<int>(), 1000);
  EXPECT_GT(r.summary.at("axial_resistance_N").at("max").get<double>(), 100.0);
}

TEST_F(MeasuredPart, RefusedWhenLoadedForASurfaceThatIsNotACylinder) {
  std::ofstream(dir_ / "hub.csv")
      << "height [mm],angle [deg],deviation [um]\n0,0,1\n0,120,1\n0,240,1\n";
  std::string text = ReadText(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios/taper-pin.yaml");
  const std::string after = "  hub:\n";
  text.insert(text.find(after) + after.size(), "    measured: {roundness: hub.csv}\n");
  std::ofstream(dir_ / "taper.yaml") << text;
  try {
    LoadScene(dir_ / "taper.yaml", registry_);
    FAIL() << "a measured taper was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "parts.hub.measured.roundness") << e.what();
    EXPECT_EQ(e.where().file, (dir_ / "taper.yaml").string());
    EXPECT_NE(std::string(e.what()).find("cylinder"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fitfeel
