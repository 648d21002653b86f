#include "framework/view/view_model.h"
#include "framework/scenario/joint_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/scenario/cad_parts.h"

namespace fitfeel::view {
namespace {

MatingPose PoseOf(const ViewSample& s) {
  MatingPose pose;
  pose.depth = s.depth;
  pose.offset = Eigen::Vector2d(s.offset_x, s.offset_z);
  pose.angle = s.angle;
  return pose;
}

// The reflection in z that takes (x, z) between the scene frame and the outer part's frame where
// the outer part moves (AnalyzerPose); nothing otherwise. Its own inverse.
Eigen::Vector2d Reflect(const Eigen::Vector2d& v, Role moving) {
  return moving == Role::kOuter ? Eigen::Vector2d(v.x(), -v.y()) : v;
}

const char* RoleName(Role role) { return role == Role::kInner ? "inner" : "outer"; }

nlohmann::json PartJson(const PartSpec& part, const SkinModelShape& sms, bool placeholder) {
  const Eigen::VectorXd& v = sms.variation;
  return {{"name", part.name},
          {"rows", sms.grid.rows},
          {"columns", sms.grid.columns},
          {"nominal_size_mm", part.size.nominal * 1e3},
          {"variation_min_um", v.size() > 0 ? v.minCoeff() * 1e6 : 0.0},
          {"variation_max_um", v.size() > 0 ? v.maxCoeff() * 1e6 : 0.0},
          {"placeholder", placeholder}};
}

// A part made of a CAD feature carries its own shape, sent once with the scene: the page draws it
// in place of the primitive surface. Whole micrometres keep the message short; the mesher's
// deflection is fifty times coarser.
void AddCadMesh(nlohmann::json* j, const std::filesystem::path& scenario_file,
                const std::string& part) {
  const std::shared_ptr<const scenario::CadMesh> mesh = scenario::CadMeshOf(scenario_file, part);
  if (!mesh) return;
  if (mesh->triangles.empty()) {
    (*j)["cad_mesh_note"] = mesh->note;
    return;
  }
  std::vector<std::int32_t> um;
  um.reserve(mesh->triangles.size());
  for (const float v : mesh->triangles) {
    um.push_back(static_cast<std::int32_t>(std::lround(static_cast<double>(v) * 1e6)));
  }
  (*j)["cad_mesh"] = {{"triangles", mesh->triangles.size() / 9}, {"positions_um", um}};
}

}  // namespace

ViewModel::~ViewModel() = default;

ViewModel::ViewModel(const Scene& scene, std::uint64_t seed, int step, bool progressive)
    : scene_(scene) {
  const PrepareWorker::Clock::time_point start = PrepareWorker::Clock::now();
  if (!scene.surface) {
    throw UserError("scene '" + scene.name + "' has no surface type '" + scene.surface_id + "'");
  }
  Rng rng(seed);
  SkinModelShapes shapes = GenerateSkinModelShapes(scene, rng);
  inner_ = std::make_unique<SkinModelShape>(std::move(shapes.inner));
  outer_ = std::make_unique<SkinModelShape>(std::move(shapes.outer));
  // The further features' shapes and then every feature's position, in Prepare's order of draws.
  std::vector<SkinModelShapes> more;
  for (std::size_t i = 1; i < scene.features.size(); ++i) {
    more.push_back(GenerateSkinModelShapes(scene.features[i], rng));
  }
  position_deviations_ = DrawPositionDeviations(scene, rng);
  const SurfaceType& surface = *scene.surface;
  if (!surface.renders_forces()) {
    status_ = "this surface type renders no forces: " + surface.limitation();
  } else {
    analyzer_ = surface.MakeContactAnalyzer();
    if (!analyzer_) {
      status_ = "surface type '" + scene.surface_id + "' provides no contact analyzer";
    } else {
      if (progressive) {
        analyzer_->PrepareStart(scene.inner, *inner_, scene.outer, *outer_, scene.model, nullptr,
                                kReadyDepth);
        rest_ = std::make_unique<PrepareWorker>(std::vector<ContactAnalyzer*>{analyzer_.get()},
                                                start, /*thread=*/true, nullptr);
      } else {
        analyzer_->Prepare(scene.inner, *inner_, scene.outer, *outer_, scene.model);
      }
      law_ = surface.MakeLaw(scene.model.law);
      law_->Prepare(scene.inner, scene.outer, scene.model);
      try {
        pressure_per_interference_ = law_->PressurePerInterference();
      } catch (const UnsupportedError&) {
        status_ = "law '" + scene.model.law + "' reports no contact pressure (no pressure map)";
      }
    }
  }
  const RenderMesh inner_mesh = surface.MakeRenderMesh(scene.inner, inner_->grid);
  const RenderMesh outer_mesh = surface.MakeRenderMesh(scene.outer, outer_->grid);
  bool placeholder = inner_mesh.empty() || outer_mesh.empty();
  nlohmann::json features = nlohmann::json::array();
  if (scene.features.empty()) {
    mesh_frames_.push_back(EncodeMeshFrame(0, inner_mesh, inner_->variation));
    mesh_frames_.push_back(EncodeMeshFrame(1, outer_mesh, outer_->variation));
  }
  for (std::size_t i = 0; i < scene.features.size(); ++i) {
    const MatingFeature& feature = scene.features[i];
    const SkinModelShape& inner = i == 0 ? *inner_ : more[i - 1].inner;
    const SkinModelShape& outer = i == 0 ? *outer_ : more[i - 1].outer;
    nlohmann::json parts = nlohmann::json::object();
    for (const Role role : {Role::kInner, Role::kOuter}) {
      const PartSpec& part = role == Role::kInner ? feature.inner : feature.outer;
      const SkinModelShape& sms = role == Role::kInner ? inner : outer;
      const RenderMesh mesh = feature.surface->MakeRenderMesh(part, sms.grid);
      placeholder = placeholder || mesh.empty();
      const PartPlacement placement = PlacementOf(feature, role, position_deviations_[i]);
      placements_.push_back(placement);
      const int side = role == Role::kInner ? 0 : 1;
      mesh_frames_.push_back(
          EncodeMeshFrame(side, PlaceMesh(placement, mesh), sms.variation, static_cast<int>(i)));
      nlohmann::json j = PartJson(part, sms, mesh.empty());
      j["body"] = placement.moving ? "moving" : "fixed";
      j["deviation_um"] = {placement.deviation.x() * 1e6, placement.deviation.y() * 1e6};
      // Only a seated part's names its seat: a scene's message stays the one its pages read.
      if (!placement.seat.isZero(0.0)) {
        j["seat_um"] = {placement.seat.x() * 1e6, placement.seat.y() * 1e6};
      }
      parts[RoleName(role)] = j;
    }
    features.push_back({{"name", feature.name},
                        {"surface", feature.surface_id},
                        {"law", feature.model.law},
                        {"moving", RoleName(feature.moving)},
                        {"at_mm", {feature.placement.at.x() * 1e3, feature.placement.at.y() * 1e3}},
                        {"angle_deg", feature.placement.angle * 180.0 / M_PI},
                        {"engages_after_mm", feature.placement.engages_after * 1e3},
                        {"inner", parts["inner"]},
                        {"outer", parts["outer"]}});
  }

  nlohmann::json j = {
      {"type", "scene"},
      {"scenario", scene.name},
      {"surface", scene.surface_id},
      {"law", scene.model.law},
      {"seed", seed},
      {"rotational", surface.rotational()},
      // A screw's page turns the moving part by the pose's angle and moves it by the depth.
      {"screw", IsScrewScene(scene)},
      {"moving", scene.moving == Role::kInner ? scene.inner.name : scene.outer.name},
      {"inner", PartJson(scene.inner, *inner_, inner_mesh.empty())},
      {"outer", PartJson(scene.outer, *outer_, outer_mesh.empty())},
      {"status", status_},
      {"placeholder_note", placeholder ? "surface type '" + scene.surface_id +
                                             "' provides no render mesh: parts drawn as "
                                             "placeholders"
                                       : ""},
      {"pressure", pressure_per_interference_ > 0.0},
      {"duration_s", scene.run.duration}};
  // Only a several-feature scene's message names the features: a one-feature scene's stays the
  // one its pages read.
  if (!scene.features.empty()) {
    j["features"] = features;
    j["moving_body"] = scene.moving_body;
    j["fixed_body"] = scene.fixed_body;
  }
  if (scene.features.empty()) {
    AddCadMesh(&j["inner"], scene.file, scene.inner.name);
    AddCadMesh(&j["outer"], scene.file, scene.outer.name);
  }
  if (step >= 0) j["step"] = step;
  scene_message_ = j.dump();
  j["companion"] = true;
  companion_message_ = j.dump();
}

const std::string& ViewModel::mesh_frame(int k) const {
  if (k < 0 || k >= mesh_count()) {
    throw UserError("viewer: mesh frame " + std::to_string(k) + " of " +
                    std::to_string(mesh_count()));
  }
  return mesh_frames_[static_cast<std::size_t>(k)];
}

MatingPose ViewModel::DatumPose(const ViewSample& sample) const {
  MatingPose pose = PoseOf(sample);
  if (scene_.features.empty()) return pose;
  // The sample's offset is in the datum's outer part's frame; the JointStage gives the datum
  // feature R(-angle) o of the body's offset o in the joint frame (its axis is the joint's), which
  // its analyzer takes in its outer part's frame.
  const double angle = scene_.features.front().placement.angle;
  pose.offset = Reflect(TurnAboutAxis(Reflect(pose.offset, scene_.moving), -angle), scene_.moving);
  return pose;
}

StateExtras ViewModel::Extras(const ViewSample& sample) const {
  StateExtras x;
  if (!analyzer_) return x;
  const MatingPose pose = DatumPose(sample);
  if (!std::isfinite(pose.depth) || !pose.offset.allFinite() || !std::isfinite(pose.angle)) {
    return x;
  }
  x.assembly_space_known = analyzer_->AssemblySpace(pose, &x.assembly_space);
  if (!scene_.features.empty()) {
    // Back into the sample's frame, where the page draws the moving axis over it.
    const double angle = scene_.features.front().placement.angle;
    for (Eigen::Vector2d& v : x.assembly_space) {
      v = Reflect(TurnAboutAxis(Reflect(v, scene_.moving), angle), scene_.moving);
    }
  }
  if (pressure_per_interference_ > 0.0) {
    Eigen::VectorXd delta;
    analyzer_->InterferenceMap(pose, &delta);
    x.pressure_max = QuantisePressure(pressure_per_interference_ * delta, &x.pressure);
  }
  return x;
}

void ViewModel::FillContact(ViewSample* sample) const {
  if (!analyzer_) return;
  ContactState c;
  analyzer_->Evaluate(DatumPose(*sample), &c);
  sample->engaged = c.engaged;
  sample->interference = c.interference;
  sample->offset_distance = c.offset_distance;
  sample->offset_angle = c.offset_angle;
  sample->assembly_extent = c.assembly_extent;
  sample->penetration = c.penetration;
  sample->max_interference = c.max_interference;
}

}  // namespace fitfeel::view
