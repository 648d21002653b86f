// What the viewer draws of a scene (ViewModel): a one-feature scene's two parts in their own
// frames (a screw's bolt meeting its nut's flanks where the page places it); a several-feature
// scene's every part, drawn as the run draws it and placed in the joint frame (PartPlacement).
#include "framework/view/view_model.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/plugin/registry.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/runtime/sequence_run.h"
#include "framework/scenario/cad_parts.h"
#include "framework/scenario/scene.h"
#include "framework/scenario/sequence.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/view/frame_codec.h"
#include "framework/view/part_placement.h"

namespace fitfeel::view {
namespace {

// Centroid and extent of a decoded mesh's corners, m.
struct MeshBox {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d min, max;
};
MeshBox BoxOf(const RenderMesh& mesh) {
  MeshBox b;
  b.min = b.max = mesh.corners.front();
  for (const Eigen::Vector3d& c : mesh.corners) {
    b.centroid += c;
    b.min = b.min.cwiseMin(c);
    b.max = b.max.cwiseMax(c);
  }
  b.centroid /= static_cast<double>(mesh.corners.size());
  return b;
}

TEST(ViewModelPlacement, PlacesAPointBackTurnedAndOnItsAxis) {
  PartPlacement p;
  p.axis = Eigen::Vector2d(10e-3, 0.0);
  p.angle = M_PI / 2;
  p.setback = 3e-3;
  // Moved back 3 mm along its own -y, then R(90 deg): (x, z) -> (z, -x), then onto its axis.
  const Eigen::Vector3d point(1e-3, -2e-3, 0.0);
  EXPECT_TRUE(PlacePoint(p, point).isApprox(Eigen::Vector3d(10e-3, -5e-3, -1e-3), 1e-12));
  // Half a turn about z first: (x, y, z) -> (-x, -y, z), so the part's body lies along +y.
  p.half_turn = true;
  EXPECT_TRUE(PlacePoint(p, point).isApprox(Eigen::Vector3d(10e-3, 5e-3, 1e-3), 1e-12));
  // Directions turn and do not move.
  EXPECT_TRUE(PlaceDirection(p, Eigen::Vector3d(1.0, 0.0, 0.0))
                  .isApprox(Eigen::Vector3d(0.0, 0.0, 1.0), 1e-12));
}

TEST(ViewModelPlacement, OneFeatureSceneSendsItsPartsInTheirOwnFrames) {
  const Scene scene =
      LoadScene("scenarios/paper-case1-h7js6.yaml", test_support::BuildTreePlugins());
  const ViewModel model(scene, 1);
  ASSERT_EQ(model.mesh_count(), 2);
  Rng rng(1);
  const SkinModelShapes shapes = GenerateSkinModelShapes(scene, rng);
  EXPECT_EQ(model.mesh_frame(0),
            EncodeMeshFrame(0, scene.surface->MakeRenderMesh(scene.inner, shapes.inner.grid),
                            shapes.inner.variation));
  EXPECT_EQ(model.mesh_frame(1),
            EncodeMeshFrame(1, scene.surface->MakeRenderMesh(scene.outer, shapes.outer.grid),
                            shapes.outer.variation));
  EXPECT_FALSE(nlohmann::json::parse(model.scene_message()).contains("features"));
  EXPECT_TRUE(model.position_deviations().empty());
}

// The keyed hub: the hub (every feature's outer part) moves. Its key stands on the shaft at
// (0, 16.3 mm), 5 mm back from the shaft's end.
TEST(ViewModelPlacement, KeyedHubDrawsBothFeaturesAtTheirPlaces) {
  const Scene scene = LoadScene("scenarios/keyed-hub.yaml", test_support::BuildTreePlugins());
  const ViewModel model(scene, 1);
  ASSERT_EQ(model.mesh_count(), 4);
  // The deviations the run draws (same scene, same seed).
  Scene seeded = scene;
  seeded.run.seed = 1;
  const PreparedScene prepared = Prepare(seeded);
  ASSERT_EQ(model.position_deviations().size(), 2u);
  for (int i = 0; i < 2; ++i) {
    for (int side = 0; side < 2; ++side) {
      EXPECT_EQ(model.position_deviations()[i][side], prepared.position_deviations[i][side]);
    }
  }
  const Eigen::Vector2d key_dev = model.position_deviations()[1][0];
  const Eigen::Vector2d keyway_dev = model.position_deviations()[1][1];
  EXPECT_GT(key_dev.norm(), 0.0);
  EXPECT_LE(key_dev.norm(), 10e-6);  // half the 20 um zone

  const DecodedMesh shaft = DecodeMeshFrame(model.mesh_frame(0));
  const DecodedMesh hub = DecodeMeshFrame(model.mesh_frame(1));
  const DecodedMesh key = DecodeMeshFrame(model.mesh_frame(2));
  const DecodedMesh keyway = DecodeMeshFrame(model.mesh_frame(3));
  EXPECT_EQ(key.feature, 1);
  EXPECT_EQ(key.part, 0);
  EXPECT_EQ(keyway.part, 1);
  // The fixed shaft's body lies along +y from its end at the joint's origin (60 mm), the moving
  // hub's behind its entrance (45 mm); both on the joint's axis.
  const MeshBox s = BoxOf(shaft.mesh), h = BoxOf(hub.mesh);
  EXPECT_NEAR(s.min.y(), 0.0, 1e-9);
  EXPECT_NEAR(s.max.y(), 60e-3, 1e-7);
  EXPECT_NEAR(h.min.y(), -45e-3, 1e-7);
  EXPECT_NEAR(h.max.y(), 0.0, 1e-9);
  EXPECT_NEAR(s.centroid.x(), 0.0, 1e-9);
  EXPECT_NEAR(s.centroid.z(), 0.0, 1e-9);
  // The key centred at z = 16.3 mm plus its deviation (to a tenth of a micrometre: the
  // deviation itself is micrometres), 5 mm back, 40 mm long; the keyway at its own deviation.
  const MeshBox k = BoxOf(key.mesh), w = BoxOf(keyway.mesh);
  EXPECT_NEAR(k.centroid.x(), key_dev.x(), 1e-7);
  EXPECT_NEAR(k.centroid.z(), 16.3e-3 + key_dev.y(), 1e-7);
  EXPECT_NEAR(k.min.y(), 5e-3, 1e-7);
  EXPECT_NEAR(k.max.y(), 45e-3, 1e-7);
  EXPECT_NEAR(k.max.z() - k.min.z(), 2.6e-3, 1e-7);  // the flank height
  EXPECT_NEAR(w.centroid.x(), keyway_dev.x(), 1e-7);
  EXPECT_NEAR(w.centroid.z(), 16.3e-3 + keyway_dev.y(), 1e-7);
  EXPECT_NEAR(w.min.y(), -45e-3, 1e-7);

  // Which body each part is on, and the features named for the page.
  ASSERT_EQ(model.placements().size(), 4u);
  for (int k2 = 0; k2 < 4; ++k2) EXPECT_EQ(model.placements()[k2].moving, k2 % 2 == 1);
  const nlohmann::json j = nlohmann::json::parse(model.scene_message());
  ASSERT_EQ(j["features"].size(), 2u);
  EXPECT_EQ(j["features"][1]["name"], "key");
  EXPECT_EQ(j["features"][1]["inner"]["body"], "fixed");
  EXPECT_EQ(j["features"][1]["outer"]["body"], "moving");
  EXPECT_NEAR(j["features"][1]["at_mm"][1].get<double>(), 16.3, 1e-9);
  EXPECT_EQ(j["moving_body"], "hub");
}

// A sequence's step (key-then-hub's hub step) with its key seated where the key step left it:
// the key (the fixed side of the key feature) drawn moved by the seat, the keyway (on the moving
// hub) not; the message names the step and the seat. A scene of its own names neither.
TEST(ViewModelPlacement, ASeatedKeyIsDrawnWhereTheEarlierStepLeftIt) {
  const Sequence sequence =
      LoadSequence("scenarios/key-then-hub.yaml", test_support::BuildTreePlugins());
  ASSERT_EQ(sequence.steps.size(), 2u);
  const Eigen::Vector2d left(2e-6, -1e-6);  // the key step's final offset; `carry: x` takes x
  const Scene seated = StepScene(sequence, 1, 1, {left});
  const Scene centred = StepScene(sequence, 1, 1, {Eigen::Vector2d::Zero()});
  EXPECT_EQ(seated.run.seed, 2u);
  const ViewModel a(seated, seated.run.seed, 1), b(centred, centred.run.seed, 1);
  ASSERT_EQ(a.placements().size(), 4u);
  EXPECT_TRUE(a.placements()[2].seat.isApprox(Eigen::Vector2d(2e-6, 0.0)));
  EXPECT_TRUE(a.placements()[2].axis.isApprox(b.placements()[2].axis + Eigen::Vector2d(2e-6, 0.0)));
  for (int k : {0, 1, 3}) {
    EXPECT_TRUE(a.placements()[k].seat.isZero(0.0)) << k;
    EXPECT_EQ(a.mesh_frame(k), b.mesh_frame(k)) << k;
  }
  const MeshBox key_a = BoxOf(DecodeMeshFrame(a.mesh_frame(2)).mesh);
  const MeshBox key_b = BoxOf(DecodeMeshFrame(b.mesh_frame(2)).mesh);
  EXPECT_NEAR(key_a.centroid.x() - key_b.centroid.x(), 2e-6, 1e-8);  // corners sent as f32
  EXPECT_NEAR(key_a.centroid.z() - key_b.centroid.z(), 0.0, 1e-8);

  const nlohmann::json j = nlohmann::json::parse(a.scene_message());
  EXPECT_EQ(j["step"], 1);
  EXPECT_EQ(j["features"][1]["inner"]["seat_um"], nlohmann::json({2.0, 0.0}));
  EXPECT_FALSE(j["features"][1]["outer"].contains("seat_um"));
  const nlohmann::json unseated = nlohmann::json::parse(b.scene_message());
  EXPECT_FALSE(unseated["features"][1]["inner"].contains("seat_um"));
  const ViewModel plain(LoadScene("scenarios/keyed-hub.yaml", test_support::BuildTreePlugins()), 1);
  EXPECT_FALSE(nlohmann::json::parse(plain.scene_message()).contains("step"));
}

// The two-pin plate: its second hole and pin 60 mm along x, each at its own deviation.
TEST(ViewModelPlacement, TwoPinPlateDrawsItsSecondHole60MillimetresAlongX) {
  const Scene scene =
      LoadScene("scenarios/two-pin-location.yaml", test_support::BuildTreePlugins());
  const ViewModel model(scene, 3);
  ASSERT_EQ(model.mesh_count(), 4);
  const Eigen::Vector2d pin_dev = model.position_deviations()[1][0];
  const Eigen::Vector2d hole_dev = model.position_deviations()[1][1];
  EXPECT_GT((pin_dev - hole_dev).norm(), 0.0);
  const MeshBox a = BoxOf(DecodeMeshFrame(model.mesh_frame(1)).mesh);
  const MeshBox pin = BoxOf(DecodeMeshFrame(model.mesh_frame(2)).mesh);
  const MeshBox hole = BoxOf(DecodeMeshFrame(model.mesh_frame(3)).mesh);
  EXPECT_NEAR(a.centroid.x(), 0.0, 1e-9);
  EXPECT_NEAR(pin.centroid.x(), 60e-3 + pin_dev.x(), 1e-7);
  EXPECT_NEAR(pin.centroid.z(), pin_dev.y(), 1e-7);
  EXPECT_NEAR(hole.centroid.x(), 60e-3 + hole_dev.x(), 1e-7);
  EXPECT_NEAR(hole.centroid.z(), hole_dev.y(), 1e-7);
  EXPECT_NEAR(hole.min.y(), -10e-3, 1e-7);  // the plate, 10 mm thick, behind its entrance
}

// A datum feature turned about the axis: its analyzer takes the pose in its own turned frame,
// and the assembly space comes back in the page's frame, turned as the feature is.
TEST(ViewModelPlacement, TurnedDatumGivesItsAssemblySpaceInThePagesFrame) {
  std::ifstream in("scenarios/keyed-hub.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string bore = "  bore:\n    surface: fitfeel.surface.cylindrical\n";
  const std::size_t at = text.find(bore);
  ASSERT_NE(at, std::string::npos);
  std::string turned_text = text;
  turned_text.insert(at + bore.size(), "    angle: 90 deg\n");
  const ViewModel plain(LoadSceneFromYaml(text, "keyed-hub.yaml", test_support::BuildTreePlugins()),
                        1);
  const ViewModel turned(
      LoadSceneFromYaml(turned_text, "turned.yaml", test_support::BuildTreePlugins()), 1);
  ViewSample sample;
  sample.depth = 20e-3;
  sample.offset_x = 2e-6;
  sample.offset_z = -1e-6;
  const StateExtras p = plain.Extras(sample), t = turned.Extras(sample);
  ASSERT_TRUE(p.assembly_space_known);
  ASSERT_GT(p.assembly_space.size(), 2u);
  ASSERT_EQ(t.assembly_space.size(), p.assembly_space.size());
  // The hub moves: the page's frame is the joint frame reflected in z, where the joint frame's
  // R(90 deg) turns (x, z) to (-z, x).
  for (std::size_t v = 0; v < p.assembly_space.size(); ++v) {
    const Eigen::Vector2d& q = p.assembly_space[v];
    EXPECT_TRUE(t.assembly_space[v].isApprox(Eigen::Vector2d(-q.y(), q.x()), 1e-9))
        << v << ": " << t.assembly_space[v].transpose() << " against " << q.transpose();
  }
}

// bolt-m10: both threads drawn as helicoids, in frames where the page's placement of the bolt
// (turned by the pose's angle, R(angle), moved by the depth) puts its flanks on the nut's at screw
// phase zero; once the run has tightened the nut, the bolt's loaded flank under pressure.
TEST(ViewModelScrew, BoltM10DrawsBothThreadsAndTheLoadedFlankOnceTightened) {
  const Scene scene = LoadScene("scenarios/bolt-m10.yaml", test_support::BuildTreePlugins());
  const ViewModel model(scene, 1);
  const nlohmann::json message = nlohmann::json::parse(model.scene_message());
  EXPECT_TRUE(message.at("screw").get<bool>());
  EXPECT_TRUE(message.at("pressure").get<bool>());
  EXPECT_EQ(message.at("placeholder_note"), "");
  ASSERT_EQ(model.mesh_count(), 2);
  const DecodedMesh bolt = DecodeMeshFrame(model.mesh_frame(0));
  const DecodedMesh nut = DecodeMeshFrame(model.mesh_frame(1));
  ASSERT_FALSE(bolt.placeholder);
  ASSERT_FALSE(nut.placeholder);
  const int columns = message.at("inner").at("columns");
  ASSERT_EQ(nut.mesh.directions.size() % columns, 0u);
  ASSERT_EQ(bolt.mesh.directions.size(),
            static_cast<std::size_t>(message.at("inner").at("rows").get<int>() * columns));

  // A corner's place on the helicoids of lead P: y - P theta / 2 pi, modulo P. Flank by flank and
  // strip by strip the two threads' corners share their radii, so at screw phase zero they share
  // this too.
  const double pitch = scene.inner.geometry->lead();
  const auto helix = [&](const Eigen::Vector3d& p) {
    return std::remainder(p.y() - pitch / (2 * M_PI) * std::atan2(-p.z(), p.x()), pitch);
  };
  const double angle = 7.9, depth = pitch * angle / (2 * M_PI);
  const double c = std::cos(angle), s = std::sin(angle);
  for (std::size_t cell = 0; cell < bolt.mesh.directions.size(); ++cell) {
    for (std::size_t q = 0; q < 4; ++q) {
      const Eigen::Vector3d p = bolt.mesh.corners[4 * cell + q];
      const Eigen::Vector3d placed(c * p.x() + s * p.z(), p.y() + depth, -s * p.x() + c * p.z());
      const Eigen::Vector3d on_nut = nut.mesh.corners[4 * (cell % columns) + q];
      ASSERT_NEAR(std::remainder(helix(placed) - helix(on_nut), pitch), 0.0, 1e-8)
          << "cell " << cell << " corner " << q;
    }
  }

  RunOptions options;
  options.clock = ClockMode::kVirtual;
  const RunResult run = RunScene(scene, options);
  ASSERT_TRUE(run.summary.at("thread").at("seated").get<bool>());
  ViewSample tightened;
  tightened.depth = run.final_pose.depth;
  tightened.angle = run.final_pose.angle;
  const StateExtras extras = model.Extras(tightened);
  EXPECT_GT(extras.pressure_max, 0.0);
  ASSERT_EQ(extras.pressure.size(), bolt.mesh.directions.size());
  // A preloaded thread bears on one flank of the bolt, within the nut (8.4 mm long).
  int pressed[2] = {0, 0};
  for (std::size_t cell = 0; cell < extras.pressure.size(); ++cell) {
    if (extras.pressure[cell] == 0) continue;
    ++pressed[cell % columns < static_cast<std::size_t>(columns) / 2 ? 0 : 1];
    const double y = bolt.mesh.corners[4 * cell].y() + tightened.depth;
    EXPECT_GT(y, -pitch) << cell;
    EXPECT_LT(y, 8.4e-3 + pitch) << cell;
  }
  EXPECT_GT(pressed[0] + pressed[1], 0);
  EXPECT_EQ(std::min(pressed[0], pressed[1]), 0) << pressed[0] << " and " << pressed[1];
  // Before the bolt reaches the nut nothing is pressed.
  ViewSample outside;
  outside.depth = -2e-3;
  EXPECT_EQ(model.Extras(outside).pressure_max, 0.0);
}

}  // namespace
}  // namespace fitfeel::view

namespace fitfeel::view {
namespace {

// A part made of a CAD feature carries its own triangles in the scene message; a part given by
// its size and geometry carries none. The resolver stands in for the STEP reader.
TEST(ViewModelCadMesh, TheSceneMessageCarriesACadPartsTrianglesOnly) {
  std::ifstream in("scenarios/paper-case1-h7g6.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string size =
      "    size: 20 mm g6          # ISO 286 table, 18-30 mm step: -20/-7 um\n";
  const std::string geometry = "    geometry: {length: 40 mm, chamfer: 0.5 mm}\n";
  ASSERT_NE(text.find(size), std::string::npos);
  ASSERT_NE(text.find(geometry), std::string::npos);
  text.replace(text.find(size), size.size(), "    cad: {file: shaft.step, feature: cylinder-1}\n");
  text.erase(text.find(geometry), geometry.size());
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("fitfeel-view-cad-" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(file) << text;
  scenario::SetCadPartResolver(
      [](const ConfigNode&, const std::string&, bool, const std::filesystem::path&) {
        scenario::CadPartKeys keys;
        keys.size = "20 mm g6";
        keys.geometry = {{"length", "40 mm"}, {"chamfer", "0.5 mm"}};
        auto mesh = std::make_shared<scenario::CadMesh>();
        mesh->triangles = {0.0f, 0.0f, 0.0f, 0.01f, 0.0f, 0.0f, 0.0f, -0.04f, 0.0f};
        keys.mesh = mesh;
        return keys;
      });
  const Scene scene = LoadScene(file, test_support::BuildTreePlugins());
  scenario::SetCadPartResolver({});
  std::filesystem::remove(file);
  const ViewModel model(scene, 1);
  const nlohmann::json message = nlohmann::json::parse(model.scene_message());
  ASSERT_TRUE(message["inner"].contains("cad_mesh")) << message["inner"].dump();
  EXPECT_EQ(message["inner"]["cad_mesh"]["triangles"], 1);
  EXPECT_EQ(message["inner"]["cad_mesh"]["positions_um"],
            nlohmann::json({0, 0, 0, 10000, 0, 0, 0, -40000, 0}));
  EXPECT_FALSE(message["outer"].contains("cad_mesh"));
  EXPECT_FALSE(message["outer"].contains("cad_mesh_note"));
}

}  // namespace
}  // namespace fitfeel::view
