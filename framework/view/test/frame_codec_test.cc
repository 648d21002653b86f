#include "framework/view/frame_codec.h"

#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel::view {
namespace {

template <typename T>
T At(const std::string& frame, std::size_t offset) {
  T value;
  std::memcpy(&value, frame.data() + offset, sizeof(T));
  return value;
}

ViewSample SampleFrame() {
  ViewSample s;
  s.time = 1.234;
  s.tick = 1234;
  s.depth = 5.5e-3;
  s.offset_x = -3e-6;
  s.offset_z = 2e-6;
  s.angle = 0.25;
  s.force[0] = 1.5;
  s.force[1] = -112.0;
  s.force[2] = -2.0;
  s.torque[1] = 0.02;
  s.assembly_extent = 4e-6;
  s.max_interference = 7e-6;
  s.stage = 1;
  s.engaged = true;
  s.interference = true;
  return s;
}

TEST(FrameCodec, StateFrameLayoutIsTheDocumentedOne) {
  StateExtras x;
  x.pressure = {0, 128, 255};
  x.pressure_max = 42e6;
  x.assembly_space = {{1e-6, 0.0}, {0.0, 1e-6}, {-1e-6, 0.0}};
  x.assembly_space_known = true;
  x.dropped = 7;
  const std::string f = EncodeStateFrame(SampleFrame(), x);
  ASSERT_EQ(f.size(), kStateFixedBytes + 3 * 8 + 3);
  EXPECT_EQ(f.substr(0, 4), "FFVW");
  EXPECT_EQ(At<std::uint16_t>(f, 4), kFrameVersion);
  EXPECT_EQ(At<std::uint16_t>(f, 6), static_cast<std::uint16_t>(FrameKind::kState));
  EXPECT_EQ(At<double>(f, 8), 1.234);
  EXPECT_EQ(At<std::uint32_t>(f, 16), 1234u);
  EXPECT_EQ(At<std::uint32_t>(f, 20), 7u);
  EXPECT_FLOAT_EQ(At<float>(f, 24), 5.5e-3f);   // depth
  EXPECT_FLOAT_EQ(At<float>(f, 44), -112.0f);   // fy
  EXPECT_EQ(At<std::uint8_t>(f, 84), 1);        // stage
  EXPECT_EQ(At<std::uint8_t>(f, 85), kEngaged | kInterference | kAssemblySpaceKnown);
  EXPECT_EQ(At<std::uint16_t>(f, 86), 3);       // polygon vertices
  EXPECT_FLOAT_EQ(At<float>(f, 88), 42e6f);     // pressure max, Pa
  EXPECT_EQ(At<std::uint32_t>(f, 92), 3u);      // pressure cells
  EXPECT_FLOAT_EQ(At<float>(f, 96), 1e-6f);     // first vertex x
  EXPECT_EQ(static_cast<std::uint8_t>(f[f.size() - 1]), 255);
}

TEST(FrameCodec, StateFrameRoundTripsAtFloatPrecision) {
  StateExtras x;
  x.pressure = {3, 0, 9, 200};
  x.pressure_max = 1e5;
  x.run_finished = true;
  const DecodedState d = DecodeStateFrame(EncodeStateFrame(SampleFrame(), x));
  const ViewSample s = SampleFrame();
  EXPECT_EQ(d.sample.time, s.time);
  EXPECT_EQ(d.sample.tick, s.tick);
  EXPECT_FLOAT_EQ(d.sample.depth, static_cast<float>(s.depth));
  EXPECT_FLOAT_EQ(d.sample.offset_x, static_cast<float>(s.offset_x));
  EXPECT_FLOAT_EQ(d.sample.force[1], -112.0f);
  EXPECT_FLOAT_EQ(d.sample.torque[1], 0.02f);
  EXPECT_FLOAT_EQ(d.sample.max_interference, 7e-6f);
  EXPECT_TRUE(d.sample.engaged);
  EXPECT_TRUE(d.sample.interference);
  EXPECT_FALSE(d.sample.guard_fault);
  EXPECT_TRUE(d.extras.run_finished);
  EXPECT_FALSE(d.extras.assembly_space_known);
  EXPECT_EQ(d.extras.pressure, x.pressure);
  EXPECT_TRUE(d.extras.assembly_space.empty());
}

TEST(FrameCodec, DecodeRefusesMalformedFrames) {
  const std::string good = EncodeStateFrame(SampleFrame(), {});
  EXPECT_THROW(DecodeStateFrame(good.substr(0, 50)), UserError);
  EXPECT_THROW(DecodeStateFrame(good + "x"), UserError);  // length disagrees with the counts
  std::string bad_magic = good;
  bad_magic[0] = 'X';
  EXPECT_THROW(DecodeStateFrame(bad_magic), UserError);
  std::string mesh_kind = good;
  mesh_kind[6] = 1;
  EXPECT_THROW(DecodeStateFrame(mesh_kind), UserError);
}

TEST(FrameCodec, QuantisedPressureKeepsTheMaximumAndRounds) {
  Eigen::VectorXd p(5);
  p << 0.0, 50e6, 100e6, -3.0, std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint8_t> q;
  EXPECT_EQ(QuantisePressure(p, &q), 100e6);
  EXPECT_EQ(q, (std::vector<std::uint8_t>{0, 128, 255, 0, 0}));  // 127.5 rounds away from zero
  EXPECT_EQ(QuantisePressure(Eigen::VectorXd::Zero(3), &q), 0.0);
  EXPECT_EQ(q, (std::vector<std::uint8_t>{0, 0, 0}));
}

TEST(FrameCodec, MeshFrameHoldsCornersDirectionsAndVariation) {
  RenderMesh mesh;
  for (int c = 0; c < 2; ++c) {
    for (int k = 0; k < 4; ++k) mesh.corners.emplace_back(c, k, 0.5);
    mesh.directions.emplace_back(1.0, 0.0, 0.0);
  }
  Eigen::VectorXd v(2);
  v << 4e-6, -2e-6;
  const std::string f = EncodeMeshFrame(1, mesh, v);
  ASSERT_EQ(f.size(), 16u + 2 * (48 + 12 + 4));
  EXPECT_EQ(At<std::uint16_t>(f, 6), static_cast<std::uint16_t>(FrameKind::kMesh));
  EXPECT_EQ(At<std::uint8_t>(f, 8), 1);  // outer
  EXPECT_EQ(At<std::uint8_t>(f, 9), 0);  // not a placeholder
  EXPECT_EQ(At<std::uint16_t>(f, 10), 0);  // the datum feature (a one-feature scene's only one)
  EXPECT_EQ(At<std::uint32_t>(f, 12), 2u);
  EXPECT_FLOAT_EQ(At<float>(f, 16 + 4 * 3 * 4 + 4), 0.0f);  // cell 1, corner 0, y
  EXPECT_FLOAT_EQ(At<float>(f, 16 + 96 + 24), 4e-6f);        // V of cell 0
  EXPECT_THROW(EncodeMeshFrame(2, mesh, v), UserError);
  EXPECT_THROW(EncodeMeshFrame(0, mesh, Eigen::VectorXd::Zero(3)), UserError);
  mesh.corners.pop_back();
  EXPECT_THROW(EncodeMeshFrame(0, mesh, v), UserError);
}

TEST(FrameCodec, MeshFrameNamesItsFeatureAndRoundTrips) {
  RenderMesh mesh;
  for (int k = 0; k < 4; ++k) mesh.corners.emplace_back(60e-3, -k * 1e-3, 16.3e-3);
  mesh.directions.emplace_back(0.0, 0.0, 1.0);
  Eigen::VectorXd v(1);
  v << -3e-6;
  const std::string f = EncodeMeshFrame(0, mesh, v, 7);
  EXPECT_EQ(At<std::uint16_t>(f, 10), 7);
  const DecodedMesh d = DecodeMeshFrame(f);
  EXPECT_EQ(d.part, 0);
  EXPECT_EQ(d.feature, 7);
  EXPECT_FALSE(d.placeholder);
  ASSERT_EQ(d.mesh.corners.size(), 4u);
  EXPECT_FLOAT_EQ(static_cast<float>(d.mesh.corners[3].y()), -3e-3f);
  EXPECT_FLOAT_EQ(static_cast<float>(d.mesh.corners[0].z()), 16.3e-3f);
  EXPECT_FLOAT_EQ(static_cast<float>(d.variation[0]), -3e-6f);
  EXPECT_THROW(EncodeMeshFrame(0, mesh, v, 65536), UserError);
  EXPECT_THROW(EncodeMeshFrame(0, mesh, v, -1), UserError);
  EXPECT_THROW(DecodeMeshFrame(f.substr(0, f.size() - 1)), UserError);
  EXPECT_THROW(DecodeMeshFrame(EncodeStateFrame(SampleFrame(), StateExtras{})), UserError);
}

TEST(FrameCodec, EmptyMeshIsAPlaceholder) {
  const std::string f = EncodeMeshFrame(0, RenderMesh{}, Eigen::VectorXd());
  ASSERT_EQ(f.size(), 16u);
  EXPECT_EQ(At<std::uint8_t>(f, 9), 1);
  EXPECT_EQ(At<std::uint32_t>(f, 12), 0u);
}

TEST(FrameCodec, HistoryFrameHasTwelveFloatsPerRow) {
  const std::vector<ViewSample> rows(3, SampleFrame());
  const std::string f = EncodeHistoryFrame(rows);
  ASSERT_EQ(f.size(), 12u + 3 * kHistoryRowFloats * 4);
  EXPECT_EQ(At<std::uint16_t>(f, 6), static_cast<std::uint16_t>(FrameKind::kHistory));
  EXPECT_EQ(At<std::uint32_t>(f, 8), 3u);
  EXPECT_FLOAT_EQ(At<float>(f, 12 + 48 + 4), 5.5e-3f);  // row 1 depth
  EXPECT_FLOAT_EQ(At<float>(f, 12 + 44), 1.0f);         // row 0 stage
}

}  // namespace
}  // namespace fitfeel::view
