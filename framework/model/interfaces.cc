// Out-of-line destructors (one vtable per interface, in the framework library) and the checking
// wrappers of the Drake-style public/protected-virtual pairs.
#include <cmath>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/discretizer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"
#include "framework/model/surface_type.h"
#include "framework/model/variation_generator.h"

namespace fitfeel {

std::string ToString(FormCharacteristic characteristic) {
  switch (characteristic) {
    case FormCharacteristic::kAxisStraightness:
      return "axis_straightness";
    case FormCharacteristic::kGeneratrixStraightness:
      return "generatrix_straightness";
    case FormCharacteristic::kRoundness:
      return "roundness";
    case FormCharacteristic::kCylindricity:
      return "cylindricity";
    case FormCharacteristic::kStraightness:
      return "straightness";
    case FormCharacteristic::kFlatness:
      return "flatness";
    case FormCharacteristic::kParallelism:
      return "parallelism";
    case FormCharacteristic::kSphericity:
      return "sphericity";
  }
  return "unknown";
}

Geometry::~Geometry() = default;
Discretizer::~Discretizer() = default;
VariationGenerator::~VariationGenerator() = default;
ContactAnalyzer::~ContactAnalyzer() = default;
ResistanceLaw::~ResistanceLaw() = default;
SurfaceType::~SurfaceType() = default;
SurfaceOptions::~SurfaceOptions() = default;

double Geometry::nominal_area() const {
  const double area = DoNominalArea();
  FITFEEL_DEMAND(area >= 0.0 && std::isfinite(area));
  return area;
}

double Geometry::mating_length() const {
  const double length = DoMatingLength();
  FITFEEL_DEMAND(length >= 0.0 && std::isfinite(length));
  return length;
}

std::string Geometry::Describe() const { return DoDescribe(); }

double Geometry::lead() const {
  const double lead = DoLead();
  FITFEEL_DEMAND(std::isfinite(lead) && lead >= 0.0);
  return lead;
}

double Geometry::DoLead() const { return 0.0; }

GridShape Discretizer::Shape(const PartSpec& part, const Resolution& resolution) const {
  if (!part.geometry) throw UserError("part '" + part.name + "' has no geometry to discretize");
  if (resolution.rows < 0 || resolution.columns < 0) {
    throw UserError("resolution of part '" + part.name + "' must not be negative");
  }
  return DoShape(part, resolution);
}

GridShape Discretizer::DoShape(const PartSpec&, const Resolution& resolution) const {
  if (resolution.is_auto()) return GridShape{};
  return GridShape{resolution.rows, resolution.columns};
}

SurfaceGrid Discretizer::Discretize(const PartSpec& part, const Resolution& resolution) const {
  Shape(part, resolution);
  SurfaceGrid grid = DoDiscretize(part, resolution);
  FITFEEL_DEMAND(grid.rows > 0 && grid.columns > 0);
  FITFEEL_DEMAND(grid.area.size() == grid.size() && grid.centre.cols() == grid.size());
  return grid;
}

SkinModelShape VariationGenerator::Generate(const PartSpec& part, const SurfaceGrid& grid,
                                            TextureMode texture, Rng& rng) const {
  if (grid.size() == 0) throw UserError("part '" + part.name + "' has an empty grid");
  if (!DoSupports(part.process.kind)) {
    throw UnsupportedError("part '" + part.name +
                           "': this surface type's generator draws only the paper's process; "
                           "process: statistical is not implemented for it yet");
  }
  SkinModelShape sms = DoGenerate(part, grid, texture, rng);
  FITFEEL_DEMAND(sms.variation.size() == grid.size());
  return sms;
}

void VariationGenerator::Configure(const SurfaceOptions& options) { DoConfigure(options); }

void VariationGenerator::DoConfigure(const SurfaceOptions&) {}

void ContactAnalyzer::Prepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                              const PartSpec& outer, const SkinModelShape& outer_sms,
                              const ModelSettings& settings) {
  Prepare(inner, inner_sms, outer, outer_sms, settings, nullptr);
}

ContactAnalyzer::ContactAnalyzer(const ContactAnalyzer& other)
    : prepared_(other.prepared_), prepared_depth_(other.prepared_depth()) {}

ContactAnalyzer& ContactAnalyzer::operator=(const ContactAnalyzer& other) {
  prepared_ = other.prepared_;
  shared_ = nullptr;
  PublishPreparedDepth(other.prepared_depth());
  return *this;
}

void ContactAnalyzer::Prepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                              const PartSpec& outer, const SkinModelShape& outer_sms,
                              const ModelSettings& settings, SharedPrepare* shared) {
  if (inner_sms.grid.size() == 0 || outer_sms.grid.size() == 0) {
    throw UserError("contact analysis needs a skin model shape for both parts");
  }
  struct Sharing {  // cleared however DoPrepare ends
    SharedPrepare*& at;
    ~Sharing() { at = nullptr; }
  } sharing{shared_};
  shared_ = shared;
  prepared_ = false;
  PublishPreparedDepth(std::numeric_limits<double>::infinity());
  DoPrepare(inner, inner_sms, outer, outer_sms, settings);
  prepared_ = true;
}

void ContactAnalyzer::PrepareStart(const PartSpec& inner, const SkinModelShape& inner_sms,
                                   const PartSpec& outer, const SkinModelShape& outer_sms,
                                   const ModelSettings& settings, SharedPrepare* shared,
                                   double ready_depth) {
  if (!DoTakesProgressivePrepare()) {
    Prepare(inner, inner_sms, outer, outer_sms, settings, shared);
    return;
  }
  if (inner_sms.grid.size() == 0 || outer_sms.grid.size() == 0) {
    throw UserError("contact analysis needs a skin model shape for both parts");
  }
  prepared_ = false;
  shared_ = shared;
  try {
    DoPrepareStart(inner, inner_sms, outer, outer_sms, settings);
    while (prepared_depth() < ready_depth && DoPrepareAhead(1)) {
    }
  } catch (...) {
    shared_ = nullptr;
    throw;
  }
  if (!(prepared_depth() < std::numeric_limits<double>::infinity())) shared_ = nullptr;
  prepared_ = true;
}

bool ContactAnalyzer::PrepareAhead(int steps) {
  if (!prepared_) throw UserError("PrepareAhead before PrepareStart");
  if (!(prepared_depth() < std::numeric_limits<double>::infinity())) return false;
  struct Sharing {  // cleared once the tables are whole, or when a step throws
    ContactAnalyzer* analyzer;
    bool more = false;
    ~Sharing() {
      if (!more) analyzer->shared_ = nullptr;
    }
  } sharing{this};
  sharing.more = DoPrepareAhead(std::max(steps, 1));
  return sharing.more;
}

void ContactAnalyzer::FinishPrepare() {
  if (!prepared_) throw UserError("FinishPrepare before PrepareStart");
  if (!(prepared_depth() < std::numeric_limits<double>::infinity())) return;
  struct Sharing {  // cleared however DoFinishPrepare ends
    SharedPrepare*& at;
    ~Sharing() { at = nullptr; }
  } sharing{shared_};
  DoFinishPrepare();
}

void ContactAnalyzer::DoPrepareStart(const PartSpec&, const SkinModelShape&, const PartSpec&,
                                     const SkinModelShape&, const ModelSettings&) {
  throw UnsupportedError("this contact analyzer prepares whole (no progressive prepare)");
}

bool ContactAnalyzer::DoPrepareAhead(int) { return false; }

void ContactAnalyzer::DoFinishPrepare() {
  while (DoPrepareAhead(std::numeric_limits<int>::max())) {
  }
}

MatingPose AnalyzerPose(const MatingPose& scene_pose, Role moving) noexcept {
  MatingPose pose = scene_pose;
  if (moving == Role::kOuter) {
    pose.offset.y() = -pose.offset.y();
    pose.tilt.y() = -pose.tilt.y();
  }
  return pose;
}

void SceneContact(ContactState* contact, Role moving) noexcept {
  if (moving != Role::kOuter) return;
  contact->offset_angle = -contact->offset_angle;
  contact->penetration_direction.y() = -contact->penetration_direction.y();
  contact->pressure_resultant.y() = -contact->pressure_resultant.y();
  contact->tilt.y() = -contact->tilt.y();
  contact->resultant_jacobian(0, 1) = -contact->resultant_jacobian(0, 1);
  contact->resultant_jacobian(1, 0) = -contact->resultant_jacobian(1, 0);
}

void ContactAnalyzer::Evaluate(const MatingPose& pose, ContactState* out) const noexcept {
  FITFEEL_DEMAND(prepared_ && out != nullptr);
  const double frontier = prepared_depth();
  if (!(pose.depth > frontier)) {
    DoEvaluate(pose, out);
    return;
  }
  // Past the frontier: the last prepared state, held (never a table entry not yet written).
  MatingPose held = pose;
  held.depth = frontier;
  DoEvaluate(held, out);
  out->held_depth = pose.depth - frontier;
}

void ContactAnalyzer::InterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const {
  if (!prepared_) throw UserError("contact analyzer queried before prepare");
  if (delta == nullptr) throw std::invalid_argument("InterferenceMap needs an output vector");
  DoInterferenceMap(pose, delta);
}

bool ContactAnalyzer::AssemblySpace(const MatingPose& pose,
                                    std::vector<Eigen::Vector2d>* polygon) const {
  if (polygon == nullptr) throw UserError("assembly space: no output polygon");
  polygon->clear();
  if (!prepared_) throw UserError("assembly space of an analyzer that is not prepared");
  return DoAssemblySpace(pose, polygon);
}

bool ContactAnalyzer::DoAssemblySpace(const MatingPose&, std::vector<Eigen::Vector2d>*) const {
  return false;
}

void ContactAnalyzer::DoInterferenceMap(const MatingPose&, Eigen::VectorXd*) const {
  throw UnsupportedError("this surface type does not produce interference maps");
}

void ResistanceLaw::Prepare(const PartSpec& inner, const PartSpec& outer,
                            const ModelSettings& settings) {
  if (settings.friction < 0.0) throw UserError("friction coefficient must not be negative");
  if (settings.contact_stiffness < 0.0) throw UserError("contact stiffness must not be negative");
  DoPrepare(inner, outer, settings);
}

void ResistanceLaw::Evaluate(const ContactState& contact, const MatingMotion& motion,
                             Wrench* out) const noexcept {
  FITFEEL_DEMAND(out != nullptr);
  DoEvaluate(contact, motion, out);
}

void ResistanceLaw::Evaluate(const ContactState& contact, const MatingMotion& motion,
                             LawState* state, Wrench* out) const noexcept {
  FITFEEL_DEMAND(out != nullptr && state != nullptr);
  DoEvaluateWithState(contact, motion, state, out);
}

void ResistanceLaw::DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                                        LawState*, Wrench* out) const noexcept {
  DoEvaluate(contact, motion, out);
}

ElasticLimitCheck ResistanceLaw::CheckElasticLimit(const ContactState& contact) const noexcept {
  return DoCheckElasticLimit(contact);
}

ElasticLimitCheck ResistanceLaw::DoCheckElasticLimit(const ContactState&) const noexcept {
  return {};
}

bool ResistanceLaw::RadialJacobian(const ContactState& contact,
                                   Eigen::Matrix2d* jacobian) const noexcept {
  FITFEEL_DEMAND(jacobian != nullptr);
  if (!contact.interference || !contact.resultant_jacobian.allFinite()) return false;
  return DoRadialJacobian(contact, jacobian);
}

bool ResistanceLaw::DoRadialJacobian(const ContactState&, Eigen::Matrix2d*) const noexcept {
  return false;
}

double ResistanceLaw::PressurePerInterference() const {
  const double coefficient = DoPressurePerInterference();
  FITFEEL_DEMAND(coefficient >= 0.0);
  return coefficient;
}

double ResistanceLaw::DoPressurePerInterference() const {
  throw UnsupportedError("this resistance law reports no contact pressure per unit interference");
}

namespace {

// The pair a surface type's meshes and lead-in are made for: the inner part, then the outer one,
// each with its parsed geometry.
void CheckInnerThenOuter(const PartSpec& inner, const PartSpec& outer, const char* what) {
  if (inner.role != Role::kInner || outer.role != Role::kOuter || inner.geometry == nullptr ||
      outer.geometry == nullptr) {
    throw UserError(std::string(what) +
                    " needs the inner part, then the outer part, each with its geometry");
  }
}

}  // namespace

std::vector<FormCharacteristic> SurfaceType::form_characteristics() const {
  return DoFormCharacteristics();
}

std::vector<SurfaceType::DeclaredCharacteristic> SurfaceType::declared_characteristics() const {
  std::vector<DeclaredCharacteristic> declared = DoDeclaredCharacteristics();
  for (const DeclaredCharacteristic& d : declared) FITFEEL_DEMAND(!d.name.empty() && d.max >= 0.0);
  return declared;
}

std::vector<SurfaceType::DeclaredCharacteristic> SurfaceType::DoDeclaredCharacteristics() const {
  return {};
}

std::vector<std::string> SurfaceType::law_names() const {
  std::vector<std::string> names = DoLawNames();
  for (const std::string& name : names) FITFEEL_DEMAND(!name.empty());
  return names;
}

bool SurfaceType::renders_forces() const { return DoRendersForces(); }

bool SurfaceType::DoRendersForces() const { return true; }

std::string SurfaceType::limitation() const {
  std::string text = DoLimitation();
  FITFEEL_DEMAND(DoRendersForces() || !text.empty());
  return text;
}

std::string SurfaceType::DoLimitation() const { return {}; }

bool SurfaceType::rotational() const { return DoRotational(); }

bool SurfaceType::DoRotational() const { return false; }

std::unique_ptr<Discretizer> SurfaceType::MakeDiscretizer() const { return DoMakeDiscretizer(); }

std::unique_ptr<VariationGenerator> SurfaceType::MakeVariationGenerator() const {
  return DoMakeVariationGenerator();
}

std::unique_ptr<ContactAnalyzer> SurfaceType::MakeContactAnalyzer() const {
  return DoMakeContactAnalyzer();
}

CoarseMeshes SurfaceType::MakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const {
  CheckInnerThenOuter(inner, outer, "coarse meshes");
  return DoMakeCoarseMeshes(inner, outer);
}

CoarseMeshes SurfaceType::DoMakeCoarseMeshes(const PartSpec&, const PartSpec&) const { return {}; }

LeadIn SurfaceType::MakeLeadIn(const PartSpec& inner, const PartSpec& outer) const {
  CheckInnerThenOuter(inner, outer, "a lead-in");
  return DoMakeLeadIn(inner, outer);
}

LeadIn SurfaceType::DoMakeLeadIn(const PartSpec&, const PartSpec&) const { return {}; }

std::shared_ptr<const Geometry> SurfaceType::ParseGeometry(const PartSpec& part,
                                                           const ConfigNode& geometry) const {
  auto parsed = DoParseGeometry(part, geometry);
  FITFEEL_DEMAND(parsed != nullptr);
  return parsed;
}

void SurfaceType::CheckPair(const PartSpec& inner, const PartSpec& outer,
                            const ConfigNode& pair_node) const {
  DoCheckPair(inner, outer, pair_node);
}

void SurfaceType::DoCheckPair(const PartSpec&, const PartSpec&, const ConfigNode&) const {}

void SurfaceType::CheckModel(const PartSpec& inner, const PartSpec& outer,
                             const ModelSettings& model, const ConfigNode& model_node) const {
  DoCheckModel(inner, outer, model, model_node);
}

std::vector<std::string> SurfaceType::DescribeModel(const PartSpec& inner, const PartSpec& outer,
                                                    const ModelSettings& model) const {
  return DoDescribeModel(inner, outer, model);
}

std::vector<std::string> SurfaceType::DoDescribeModel(const PartSpec&, const PartSpec&,
                                                      const ModelSettings&) const {
  return {};
}

void SurfaceType::DoCheckModel(const PartSpec&, const PartSpec&, const ModelSettings&,
                               const ConfigNode&) const {}

std::shared_ptr<const SurfaceOptions> SurfaceType::ParseOptions(const ConfigNode& options) const {
  if (!options.is_map()) options.Fail("a map of surface-specific options", options.Describe());
  options.Keys();  // no repeated keys
  auto parsed = DoParseOptions(options);
  FITFEEL_DEMAND(parsed != nullptr);
  return parsed;
}

std::shared_ptr<const SurfaceOptions> SurfaceType::DoParseOptions(const ConfigNode& options) const {
  options.ExpectOnlyKeys({});
  return std::make_shared<const SurfaceOptions>();
}

double SurfaceType::EstimatePrepareSeconds(const ModelSettings& model, const GridShape& inner,
                                           const GridShape& outer, double depth_steps) const {
  if (inner.rows < 0 || inner.columns < 0 || outer.rows < 0 || outer.columns < 0 ||
      !(depth_steps >= 0.0) || !std::isfinite(depth_steps)) {
    throw UserError(
        "a prepare estimate needs non-negative grids and a finite, non-negative "
        "number of depth steps");
  }
  const double seconds = DoEstimatePrepareSeconds(model, inner, outer, depth_steps);
  FITFEEL_DEMAND(seconds >= 0.0 && std::isfinite(seconds));
  return seconds;
}

double SurfaceType::DoEstimatePrepareSeconds(const ModelSettings&, const GridShape&,
                                             const GridShape&, double) const {
  return 0.0;
}

std::vector<CharacteristicCheck> SurfaceType::EvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  if (sms.variation.size() != sms.grid.size() || sms.grid.size() == 0) {
    throw UserError("part '" + part.name + "': skin model shape does not match its grid");
  }
  return DoEvaluateCharacteristics(part, sms);
}

std::vector<CharacteristicCheck> SurfaceType::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape&) const {
  throw UnsupportedError("part '" + part.name +
                         "': this surface type cannot evaluate its characteristics yet");
}

RenderMesh SurfaceType::MakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const {
  if (grid.size() <= 0 || grid.centre.cols() != grid.size() || grid.normal.cols() != grid.size()) {
    throw UserError("part '" + part.name + "': render mesh of an empty or inconsistent grid");
  }
  RenderMesh mesh = DoMakeRenderMesh(part, grid);
  if (mesh.empty() && mesh.corners.empty()) return mesh;
  const auto cells = static_cast<std::size_t>(grid.size());
  if (mesh.directions.size() != cells || mesh.corners.size() != 4 * cells) {
    throw UserError("part '" + part.name + "': the surface plugin's render mesh has " +
                    std::to_string(mesh.corners.size()) + " corners and " +
                    std::to_string(mesh.directions.size()) + " directions for " +
                    std::to_string(cells) + " cells (expected 4 corners and 1 direction each)");
  }
  return mesh;
}

RenderMesh SurfaceType::DoMakeRenderMesh(const PartSpec&, const SurfaceGrid&) const { return {}; }

std::unique_ptr<ResistanceLaw> SurfaceType::MakeLaw(std::string_view name) const {
  const auto names = law_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string offered;
    for (const auto& n : names) offered += (offered.empty() ? "" : ", ") + n;
    throw UserError("unknown resistance law '" + std::string(name) +
                    "'; this surface offers: " + (offered.empty() ? "none" : offered));
  }
  auto law = DoMakeLaw(name);
  if (!law) throw UnsupportedError("resistance law '" + std::string(name) + "' is not available");
  return law;
}

}  // namespace fitfeel
