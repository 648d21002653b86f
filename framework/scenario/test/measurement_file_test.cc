// Measurement files: what they read in SI, and every refusal located at file:line:column with the
// scenario key that named the file.
#include "framework/scenario/measurement_file.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel::scenario {
namespace {

namespace fs = std::filesystem;

class MeasurementFileTest : public ::testing::Test {
 protected:
  MeasurementFileTest()
      : dir_(fs::temp_directory_path() /
             (std::string("fitfeel_measurement_file_") +
              ::testing::UnitTest::GetInstance()->current_test_info()->name())),
        scene_(ConfigNode::Parse("measured:\n  roundness: part.csv\n", "scene.yaml")),
        key_(scene_.Child("measured").Child("roundness")) {
    fs::create_directories(dir_);
  }
  ~MeasurementFileTest() override { fs::remove_all(dir_); }

  fs::path Write(const std::string& text) const {
    const fs::path file = dir_ / "part.csv";
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  MeasuredSurface Read(const std::string& text,
                       MeasurementKind kind = MeasurementKind::kRoundness) const {
    return ReadMeasurement(Write(text), kind, 0.01, key_);
  }
  // The refusal of `text`: its line, column and what it says.
  ScenarioError Refusal(const std::string& text,
                        MeasurementKind kind = MeasurementKind::kRoundness) const {
    try {
      Read(text, kind);
    } catch (const ScenarioError& e) {
      return e;
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return ScenarioError({}, "", "", "");
  }

  fs::path dir_;
  ConfigNode scene_;
  ConfigNode key_;
};

TEST_F(MeasurementFileTest, ReadsTracesInTheirUnits) {
  const MeasuredSurface m = Read(
      "# a roundness tester's export\n"
      "angle [deg], height [mm], radius [mm]\n"
      "0, 1, 10.001\n90, 1, 10.002\n-90, 1, 10.003\n\n"
      "0, 2, 10.0\r\n90, 2, 10.0\r45,2,10.0\n");
  ASSERT_EQ(m.value.size(), 6u);
  EXPECT_TRUE(m.absolute);
  EXPECT_EQ(m.traces, 2);
  EXPECT_DOUBLE_EQ(m.height[0], 1e-3);
  EXPECT_DOUBLE_EQ(m.angle[1], std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(m.angle[2], 1.5 * std::numbers::pi);  // -90 degrees, in [0, 2 pi)
  EXPECT_NEAR(m.value[2], 0.010003, 1e-15);
}

TEST_F(MeasurementFileTest, ReadsPointCloudsAsRadiusAngleHeight) {
  const MeasuredSurface m = Read("x [mm],y [mm],z [mm]\n10,0,0\n0,5,10.002\n-10,1,0\n",
                                 MeasurementKind::kPoints);
  ASSERT_EQ(m.value.size(), 3u);
  EXPECT_DOUBLE_EQ(m.value[1], 0.010002);
  EXPECT_DOUBLE_EQ(m.angle[1], std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(m.height[1], 0.005);
  EXPECT_DOUBLE_EQ(m.angle[2], std::numbers::pi);
}

TEST_F(MeasurementFileTest, RefusalsNameFileLineColumnAndKey) {
  struct Case {
    std::string text;
    int line, column;
    std::string says;
  };
  const std::string head = "height [um],angle [rad],deviation [um]\n";
  const Case cases[] = {
      {"", 0, 1, "no header"},
      {"height [um],angle [rad]\n", 1, 1, "neither"},
      {"angle [rad],deviation [um]\n", 1, 1, "no column 'height'"},
      {"height [um],angle [rad],deviation [um],radius [mm]\n", 1, 1, "both"},
      {"height [um],angle,deviation [um]\n", 1, 13, "'angle'"},
      {"height [um],angle [rad],deviation [N]\n", 1, 25, "a unit of a length"},
      {"height [um],angle [rad],colour [um]\n", 1, 25, "a column 'colour'"},
      {head + "0,0,1\n0,1,abc\n", 3, 5, "'abc'"},
      {head + "0,0,1\n0,1\n", 3, 1, "3 cells"},
      {head + "0,0,nan\n", 2, 5, "'nan'"},
      {head + "0,0,2000\n", 2, 5, "a deviation within 1 mm"},
      {head + "0,0,1\n0,1,1\n0,2,1\n0,1,1\n", 5, 1, "a repeated angle (line 3)"},
      {head + "0,0,1\n0,1,1\n0,2,1\n5,1,1\n", 5, 1, "at least 3 samples"},
      {head, 1, 1, "at least one sample"},
      {"height [mm],angle [deg],radius [um]\n1,0,10\n", 2, 5, "a radius within 1 mm"},
  };
  for (const Case& c : cases) {
    const ScenarioError e = Refusal(c.text);
    EXPECT_EQ(e.where().file, (dir_ / "part.csv").string()) << c.text;
    EXPECT_EQ(e.where().line, c.line) << c.text << "\n" << e.what();
    EXPECT_EQ(e.where().column, c.column) << c.text << "\n" << e.what();
    EXPECT_EQ(e.key_path(), "measured.roundness") << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
  const ScenarioError far =
      Refusal("x [m],y [m],z [m]\n0.01,0,0\n0.02,0,0\n", MeasurementKind::kPoints);
  EXPECT_EQ(far.where().line, 3);
  EXPECT_NE(far.found().find("20 mm"), std::string::npos) << far.what();
}

TEST_F(MeasurementFileTest, AMissingFileIsRefusedAtItsKey) {
  try {
    ReadMeasurement(dir_ / "absent.csv", MeasurementKind::kRoundness, 0.01, key_);
    FAIL() << "accepted a missing file";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.where().file, "scene.yaml");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(e.found().find("absent.csv"), std::string::npos) << e.what();
  }
  // A device never ends: refused before reading.
  EXPECT_THROW(ReadMeasurement("/dev/zero", MeasurementKind::kPoints, 0.01, key_), ScenarioError);
  EXPECT_THROW(ReadMeasurement(dir_, MeasurementKind::kPoints, 0.01, key_), ScenarioError);
}

// The file is read a block at a time: a line ending split between two blocks (CR at the end of
// one, LF at the start of the next) is one ending, and lines keep the numbers an editor shows.
TEST_F(MeasurementFileTest, ALineEndingAcrossTwoBlocksIsOneEnding) {
  const std::size_t block = std::size_t{1} << 16;
  const std::string head = "height [um],angle [rad],deviation [um]\n";
  std::string text = head + "# " + std::string(block - head.size() - 3, 'c') + "\r\n";
  ASSERT_EQ(text[block - 1], '\r');
  text += "0,0,1\r\n0,1,1\r0,2,1\n0,2,x\n";
  const ScenarioError e = Refusal(text);
  EXPECT_EQ(e.where().line, 6) << e.what();
  EXPECT_EQ(e.where().column, 5) << e.what();
}

TEST_F(MeasurementFileTest, ALineLongerThanTheCapIsRefusedAtItsStart) {
  const std::string head = "height [um],angle [rad],deviation [um]\n";
  const ScenarioError e =
      Refusal(head + "0,0,1\n" + std::string(kMaxMeasurementLineBytes + 1, '7') + "\n0,1,1\n");
  EXPECT_EQ(e.where().line, 3) << e.what();
  EXPECT_EQ(e.where().column, 1) << e.what();
  EXPECT_NE(e.expected().find("a line of at most 65536 bytes"), std::string::npos) << e.what();
  EXPECT_EQ(e.found(), "a longer line: '" + std::string(40, '7') + "'...") << e.what();
  // A line of exactly the cap is read (and refused for what it holds, not for its length).
  const ScenarioError at_cap =
      Refusal(head + "0,0,1\n" + std::string(kMaxMeasurementLineBytes, '7') + "\n");
  EXPECT_EQ(at_cap.expected(), "3 cells, as the header") << at_cap.what();
}

// A found text is whole in the message: quoted, its control bytes (a NUL would end the message
// where it is printed) escaped, cut to 40 characters with "...", never inside a UTF-8 character.
TEST_F(MeasurementFileTest, AFoundTextIsEscapedAndShortened) {
  const std::string head = "height [um],angle [rad],deviation [um]\n";
  ScenarioError e = Refusal(head + "0,0," + std::string("1\0\x01x", 4) + "\n");
  EXPECT_EQ(e.found(), "'1\\x00\\x01x'");
  EXPECT_EQ(std::string(e.what()).size(), std::strlen(e.what())) << "a NUL in the message";
  e = Refusal(head + "0,0," + std::string(1000, 'z') + "\n");
  EXPECT_EQ(e.found(), "'" + std::string(40, 'z') + "'...");
  std::string micro;
  for (int k = 0; k < 30; ++k) micro += "\xc2\xb5";  // 30 x 'µ', two bytes each
  e = Refusal(head + "0,0," + std::string(20, 'a') + micro + "\n");
  EXPECT_EQ(e.found(), "'" + std::string(20, 'a') + micro.substr(0, 40) + "'...");
  e = Refusal("height [um],angle [rad],deviation [" + std::string(200, 'u') + "]\n");
  EXPECT_EQ(e.found(), "'" + std::string(40, 'u') + "'...") << e.what();
}

}  // namespace
}  // namespace fitfeel::scenario
