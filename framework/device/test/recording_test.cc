#include "framework/device/recording.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

class RecordingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fitfeel_recording_test_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path Write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  fs::path dir_;
};

std::vector<RecordedSample> MakeSamples(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<RecordedSample> out(n);
  for (int i = 0; i < n; ++i) {
    RecordedSample& s = out[i];
    s.time = i * 1e-3;
    s.position = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 1e-2;
    s.orientation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
    s.velocity = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 0.1;
    s.angular_velocity = Eigen::Vector3d(g(rng), g(rng), g(rng));
    s.buttons = static_cast<std::uint32_t>(rng() & 0xF);
    s.commanded.force = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 3.0;
    s.commanded.torque = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 1e-3;
    s.delivered.force = s.commanded.force * 0.999;
    s.delivered.torque = Eigen::Vector3d(1e-300, -0.0, 5e-324);  // extremes survive too
  }
  return out;
}

bool BitEqual(const RecordedSample& a, const RecordedSample& b) {
  auto same = [](const double* x, const double* y, int n) {
    return std::memcmp(x, y, sizeof(double) * n) == 0;
  };
  return same(&a.time, &b.time, 1) && same(a.position.data(), b.position.data(), 3) &&
         same(a.orientation.coeffs().data(), b.orientation.coeffs().data(), 4) &&
         same(a.velocity.data(), b.velocity.data(), 3) &&
         same(a.angular_velocity.data(), b.angular_velocity.data(), 3) && a.buttons == b.buttons &&
         same(a.commanded.force.data(), b.commanded.force.data(), 3) &&
         same(a.commanded.torque.data(), b.commanded.torque.data(), 3) &&
         same(a.delivered.force.data(), b.delivered.force.data(), 3) &&
         same(a.delivered.torque.data(), b.delivered.torque.data(), 3);
}

TEST_F(RecordingTest, RoundTripsBitForBit) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const std::vector<RecordedSample> samples = MakeSamples(seed, 500);
    const fs::path p = dir_ / "run.rec";
    WriteRecording(p, {"PHANTOM Desktop"}, samples);
    const Recording back = ReadRecording(p);
    EXPECT_EQ(back.info.device_model, "PHANTOM Desktop");
    ASSERT_EQ(back.samples.size(), samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      ASSERT_TRUE(BitEqual(samples[i], back.samples[i])) << "seed " << seed << " sample " << i;
    }
    EXPECT_FALSE(fs::exists(dir_ / "run.rec.partial"));
  }
}

TEST_F(RecordingTest, HeaderCarriesUnitsAndVersion) {
  const fs::path p = dir_ / "one.rec";
  WriteRecording(p, {}, MakeSamples(1, 1));
  std::ifstream in(p);
  std::string first, header;
  std::getline(in, first);
  std::getline(in, header);
  EXPECT_EQ(first, "# fitfeel-recording 2");
  EXPECT_EQ(header.rfind("t_s x_m y_m z_m qw_1", 0), 0u) << header;
  EXPECT_NE(header.find("fx_cmd_N"), std::string::npos);
  EXPECT_NE(header.find("tz_dlv_N*m"), std::string::npos);
}

TEST_F(RecordingTest, EmptyRecordingIsValid) {
  const fs::path p = dir_ / "empty.rec";
  WriteRecording(p, {}, {});
  EXPECT_TRUE(ReadRecording(p).samples.empty());
}

TEST_F(RecordingTest, WriterRefusesBadSamplesAndWritesNothing) {
  std::vector<RecordedSample> samples = MakeSamples(2, 3);
  samples[1].velocity.y() = std::nan("");
  const fs::path p = dir_ / "bad.rec";
  EXPECT_THROW(WriteRecording(p, {}, samples), UserError);
  EXPECT_FALSE(fs::exists(p));
  samples = MakeSamples(2, 3);
  samples[2].time = samples[1].time;
  EXPECT_THROW(WriteRecording(p, {}, samples), UserError);
  EXPECT_FALSE(fs::exists(p));
  EXPECT_THROW(WriteRecording(dir_ / "no" / "such" / "dir.rec", {}, MakeSamples(1, 2)), UserError);
}

// Text of a valid two-sample file, to break in the tests below.
std::string ValidText(const fs::path& scratch) {
  WriteRecording(scratch, {"Touch"}, MakeSamples(3, 2));
  std::ifstream in(scratch, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

std::string Join(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

void ExpectRecordingRefused(const fs::path& p, int line, const std::string& reason_part) {
  try {
    ReadRecording(p);
    ADD_FAILURE() << "accepted " << p << ", expected refusal at line " << line;
  } catch (const RecordingError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.reason().find(reason_part), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(p.filename().string() + ":" + std::to_string(line)),
              std::string::npos)
        << e.what();
  }
}

TEST_F(RecordingTest, RefusesMalformedFilesWithLineAndReason) {
  const std::vector<std::string> good = Lines(ValidText(dir_ / "good.rec"));
  // good: 1 format, 2 device, 3 header, 4-5 samples, 6 end.
  ASSERT_EQ(good.size(), 6u);
  auto with = [&](int index, const std::string& replacement) {
    std::vector<std::string> l = good;
    l[index] = replacement;
    return Join(l);
  };
  ExpectRecordingRefused(Write("a.rec", with(0, "fitfeel recording")), 1,
                         "not a fitfeel recording");
  ExpectRecordingRefused(Write("b.rec", with(0, "# fitfeel-recording 7")), 1, "unsupported");
  std::string header = good[2];
  ExpectRecordingRefused(Write("c.rec", with(2, "t " + header.substr(4))), 3, "has no unit");
  std::string wrong_unit = header;
  wrong_unit.replace(wrong_unit.find("x_m"), 3, "x_mm");
  ExpectRecordingRefused(Write("d.rec", with(2, wrong_unit)), 3, "is in 'mm', expected 'm'");
  std::string no_unit_cmd = header;
  no_unit_cmd.replace(no_unit_cmd.find("fx_cmd_N"), 8, "fx_cmd");
  ExpectRecordingRefused(Write("e.rec", with(2, no_unit_cmd)), 3, "has no unit");
  ExpectRecordingRefused(Write("f.rec", with(3, good[3] + " 1.0")), 4, "30 fields, expected 29");
  std::string bad_number = good[4];
  bad_number.replace(bad_number.find(' ') + 1, 0, "x");
  ExpectRecordingRefused(Write("g.rec", with(4, bad_number)), 5, "not a finite number");
  std::string nan_field = good[4];
  nan_field.replace(nan_field.find(' ') + 1, 0, "nan ");
  nan_field = nan_field.substr(0, nan_field.rfind(' '));
  ExpectRecordingRefused(Write("h.rec", with(4, nan_field)), 5, "not a finite number");
  // Time going backwards: the second sample takes the first's time.
  std::string same_time = good[4];
  same_time = good[3].substr(0, good[3].find(' ')) + same_time.substr(same_time.find(' '));
  ExpectRecordingRefused(Write("i.rec", with(4, same_time)), 5, "does not come after");
  ExpectRecordingRefused(Write("j.rec", with(5, "# end: 3 samples")), 6, "announces 3 samples");
  // Truncations: no end line; cut mid-line; nothing after the format line.
  std::vector<std::string> cut(good.begin(), good.end() - 1);
  ExpectRecordingRefused(Write("k.rec", Join(cut)), 5, "truncated");
  const std::string text = Join(good);
  ExpectRecordingRefused(Write("l.rec", text.substr(0, text.size() - 40)), 5, "truncated");
  ExpectRecordingRefused(Write("m.rec", good[0] + "\n"), 1, "truncated: no column header");
  ExpectRecordingRefused(Write("n.rec", ""), 1, "empty file");
  ExpectRecordingRefused(Write("o.rec", Join(good) + "0 0\n"), 7, "after the end line");
  // The first sample with field `index` replaced.
  auto with_field = [&](int index, const std::string& value) {
    std::vector<std::string> f;
    std::stringstream s(good[3]);
    for (std::string w; s >> w;) f.push_back(w);
    f[index] = value;
    std::string line;
    for (const std::string& w : f) line += (line.empty() ? "" : " ") + w;
    return line;
  };
  ExpectRecordingRefused(Write("p.rec", with(3, with_field(4, "2"))), 4, "unit length");
  // Finite but absurd: a position of 1e308 m once reached trace.csv as inf.
  ExpectRecordingRefused(Write("q.rec", with(3, with_field(1, "1e308"))), 4,
                         "outside physical sense");
  ExpectRecordingRefused(Write("s.rec", with(3, with_field(9, "-1e3"))), 4,
                         "outside physical sense");
  // Lone CR line endings read as lines.
  std::string cr = Join(good);
  for (char& c : cr) {
    if (c == '\n') c = '\r';
  }
  EXPECT_EQ(ReadRecording(Write("r.rec", cr)).samples.size(), 2u);
  try {
    ReadRecording(dir_ / "missing.rec");
    ADD_FAILURE();
  } catch (const RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

}  // namespace
}  // namespace fitfeel
