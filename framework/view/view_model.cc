#include "framework/view/view_model.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/runtime/prepare.h"

namespace fitfeel::view {
namespace {

MatingPose PoseOf(const ViewSample& s) {
  MatingPose pose;
  pose.depth = s.depth;
  pose.offset = Eigen::Vector2d(s.offset_x, s.offset_z);
  pose.angle = s.angle;
  return pose;
}

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

}  // namespace

ViewModel::~ViewModel() = default;

ViewModel::ViewModel(const Scene& scene, std::uint64_t seed) : scene_(scene) {
  if (!scene.surface) {
    throw UserError("scene '" + scene.name + "' has no surface type '" + scene.surface_id + "'");
  }
  Rng rng(seed);
  SkinModelShapes shapes = GenerateSkinModelShapes(scene, rng);
  inner_ = std::make_unique<SkinModelShape>(std::move(shapes.inner));
  outer_ = std::make_unique<SkinModelShape>(std::move(shapes.outer));
  const SurfaceType& surface = *scene.surface;
  if (!surface.renders_forces()) {
    status_ = "this surface type renders no forces: " + surface.limitation();
  } else {
    analyzer_ = surface.MakeContactAnalyzer();
    if (!analyzer_) {
      status_ = "surface type '" + scene.surface_id + "' provides no contact analyzer";
    } else {
      analyzer_->Prepare(scene.inner, *inner_, scene.outer, *outer_, scene.model);
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
  mesh_frames_[0] = EncodeMeshFrame(0, inner_mesh, inner_->variation);
  mesh_frames_[1] = EncodeMeshFrame(1, outer_mesh, outer_->variation);

  const bool placeholder = inner_mesh.empty() || outer_mesh.empty();
  nlohmann::json j = {
      {"type", "scene"},
      {"scenario", scene.name},
      {"surface", scene.surface_id},
      {"law", scene.model.law},
      {"seed", seed},
      {"rotational", surface.rotational()},
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
  scene_message_ = j.dump();
}

const std::string& ViewModel::mesh_frame(int part) const {
  if (part != 0 && part != 1) throw UserError("viewer: part must be 0 (inner) or 1 (outer)");
  return mesh_frames_[part];
}

StateExtras ViewModel::Extras(const ViewSample& sample) const {
  StateExtras x;
  if (!analyzer_) return x;
  const MatingPose pose = PoseOf(sample);
  if (!std::isfinite(pose.depth) || !pose.offset.allFinite() || !std::isfinite(pose.angle)) {
    return x;
  }
  x.assembly_space_known = analyzer_->AssemblySpace(pose, &x.assembly_space);
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
  analyzer_->Evaluate(PoseOf(*sample), &c);
  sample->engaged = c.engaged;
  sample->interference = c.interference;
  sample->offset_distance = c.offset_distance;
  sample->offset_angle = c.offset_angle;
  sample->assembly_extent = c.assembly_extent;
  sample->penetration = c.penetration;
  sample->max_interference = c.max_interference;
}

}  // namespace fitfeel::view
