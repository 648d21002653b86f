#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/collision/coarse_mesh.h"
#include "framework/collision/lead_in.h"
#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/discretizer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"
#include "framework/model/render_mesh.h"
#include "framework/model/resistance_law.h"
#include "framework/model/variation_generator.h"

namespace fitfeel {

// One evaluated characteristic of a skin model shape against the tolerance it came from.
struct CharacteristicCheck {
  std::string name;    // "two_point_size_max", "roundness", "axis_straightness", ...
  double value = 0.0;  // evaluated, m
  double lower = 0.0;  // allowed range, m (a form tolerance is [0, t])
  double upper = 0.0;
  bool pass() const { return value >= lower && value <= upper; }
};

// What a surface plugin registers: one kind of mating surface (cylindrical, planar, ...) with the
// four model interfaces of the design card. Objects it makes keep their plugin library loaded (the
// registry never unloads a library). Every public method is non-virtual: it checks its arguments
// (and what the plugin returns) and calls the protected virtual Do... that a plugin overrides.
class FITFEEL_API SurfaceType {
 public:
  virtual ~SurfaceType();

  // Parses and checks one part's `geometry` node; throws ScenarioError at the offending key.
  // `part` holds everything the scenario said of the part except its geometry (name, role, size,
  // form, texture, material): the mating size comes from `part.size.nominal`.
  std::shared_ptr<const Geometry> ParseGeometry(const PartSpec& part,
                                                const ConfigNode& geometry) const;
  // Checks the pair as a whole once both parts are parsed (e.g. the nominal sizes agree);
  // throws ScenarioError at `pair_node`.
  void CheckPair(const PartSpec& inner, const PartSpec& outer, const ConfigNode& pair_node) const;
  // Checks the parsed model against the parts once both are known (a thread's joint against the
  // bolt's size and length); throws ScenarioError at the offending key under `model_node`.
  void CheckModel(const PartSpec& inner, const PartSpec& outer, const ModelSettings& model,
                  const ConfigNode& model_node) const;
  // What the model makes of the parts, for `fitfeel validate`: lines a person reads before a run
  // (a thread's joint: its compliances, VDI 2230's preload for a torque). Empty by default. Not
  // for the tick; throws UserError as the model's own prepare would.
  std::vector<std::string> DescribeModel(const PartSpec& inner, const PartSpec& outer,
                                         const ModelSettings& model) const;
  // Parses and checks the scenario's `model.options` map (surface-specific model switches) once,
  // when the scene loads; throws ScenarioError at the offending key. The result, never null, is
  // the scene's ModelSettings::options, which the surface's objects read (OptionsAs).
  std::shared_ptr<const SurfaceOptions> ParseOptions(const ConfigNode& options) const;

  // Form characteristics this surface type models; others in a scenario are refused.
  std::vector<FormCharacteristic> form_characteristics() const;
  // Tolerance characteristics of its own that the surface type reads from a part's `form:` map
  // beside the ISO 1101 ones (into FormSpec::declared): a zone limit in [0, max] with its
  // dimension. Limits that depend on the geometry are the surface type's to check in
  // ParseGeometry.
  struct DeclaredCharacteristic {
    std::string name;
    Dimension dimension;
    double max;
  };
  std::vector<DeclaredCharacteristic> declared_characteristics() const;
  // Law names this surface offers; the first is the default. None when it renders no forces.
  std::vector<std::string> law_names() const;
  // False for a surface type that can be discretised but has no resistance law yet (a test double);
  // `limitation()` then says why (never empty then), and running a scene with it is refused with
  // that message.
  bool renders_forces() const;
  std::string limitation() const;
  // The constrained motion: translation along the mating axis, or rotation about it / the centre.
  bool rotational() const;

  // Evaluates every characteristic of `part`'s spec (size limits, each form tolerance) on a
  // generated skin model shape, as a metrologist would (minimum zone where ISO defaults to it).
  // Used by `fitfeel sms` and by the conformance suite. Not for the tick.
  std::vector<CharacteristicCheck> EvaluateCharacteristics(const PartSpec& part,
                                                           const SkinModelShape& sms) const;

  // New objects of the surface's model classes; null when the surface type provides none (a
  // test double), which whoever prepares a scene refuses. A surface that cannot make one yet
  // throws UnsupportedError saying why.
  std::unique_ptr<Discretizer> MakeDiscretizer() const;
  std::unique_ptr<VariationGenerator> MakeVariationGenerator() const;
  std::unique_ptr<ContactAnalyzer> MakeContactAnalyzer() const;
  // Throws UserError naming the offered laws if `name` is not one of them.
  std::unique_ptr<ResistanceLaw> MakeLaw(std::string_view name) const;

  // What preparing the scene's law costs beyond the loader's per-cell estimate (scene.h
  // SceneCost), in seconds on one core of the reference machine, for the loader's admission: a
  // law whose prepare is not proportional to the cells says so here (the cylinder's elastic
  // solve grows with the rows cubed). The grids are the parts' (Discretizer::Shape), `depth_steps`
  // the depth tables' rows. Throws UserError for negative or non-finite inputs, ScenarioError
  // from a surface's own option keys; the estimate is finite and non-negative.
  double EstimatePrepareSeconds(const ModelSettings& model, const GridShape& inner,
                                const GridShape& outer, double depth_steps) const;

  // The parts' coarse meshes for collision in free motion (the positioning stage's FCL query),
  // in the frames CoarseMeshes describes; built once before a run, never in the tick. Empty
  // meshes mean this surface type models no collision in free motion (the moving part passes
  // through the fixed one without resistance until the constrained stage takes over). Throws
  // UserError unless `inner` and `outer` are the inner and the outer part, each with its
  // geometry, or if the parts cannot be meshed.
  CoarseMeshes MakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const;

  // The lead-in of the pair (LeadIn, described with the inner part moving; the positioning stage
  // uses it for either part moving): the free region its chamfers leave an aligned moving part,
  // in which the positioning stage guides the part as a god object, and the depth at which the
  // constrained stage takes over. Built once before a run. Empty: no lead-in (free motion
  // collides the coarse meshes, if any, and the hand-over asks for the part near the axis at the
  // entrance). Throws UserError as MakeCoarseMeshes does, or if the parts cannot be profiled.
  LeadIn MakeLeadIn(const PartSpec& inner, const PartSpec& outer) const;

  // The render mesh of `part`'s mating surface on its grid, for a viewer (RenderMesh says the
  // frames); not for the tick. Empty when the surface type provides none (the default): a viewer
  // then draws a placeholder that says so. Throws UserError for a grid that does not match the
  // part, or when the plugin's mesh does not match the grid (4 corners and 1 direction per cell).
  RenderMesh MakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const;

 protected:
  virtual std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                          const ConfigNode& geometry) const = 0;
  // Default: no check of the pair.
  virtual void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                           const ConfigNode& pair_node) const;
  // Default: nothing to say.
  virtual std::vector<std::string> DoDescribeModel(const PartSpec& inner, const PartSpec& outer,
                                                   const ModelSettings& model) const;
  // Default: no check of the model against the parts.
  virtual void DoCheckModel(const PartSpec& inner, const PartSpec& outer,
                            const ModelSettings& model, const ConfigNode& model_node) const;
  // Default: the surface takes no options, so any key is unknown (a plain SurfaceOptions).
  virtual std::shared_ptr<const SurfaceOptions> DoParseOptions(const ConfigNode& options) const;
  virtual std::vector<FormCharacteristic> DoFormCharacteristics() const = 0;
  // Default: none.
  virtual std::vector<DeclaredCharacteristic> DoDeclaredCharacteristics() const;
  virtual std::vector<std::string> DoLawNames() const = 0;
  // Default: true, with no limitation.
  virtual bool DoRendersForces() const;
  virtual std::string DoLimitation() const;
  // Default: false (a translation along the mating axis).
  virtual bool DoRotational() const;
  // Default: throws UnsupportedError (a surface type without a metrology binding yet).
  virtual std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const;
  virtual std::unique_ptr<Discretizer> DoMakeDiscretizer() const = 0;
  virtual std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const = 0;
  virtual std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const = 0;
  virtual std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const = 0;
  // Default: 0 (the per-cell estimate covers the surface's laws).
  virtual double DoEstimatePrepareSeconds(const ModelSettings& model, const GridShape& inner,
                                          const GridShape& outer, double depth_steps) const;
  // Default: empty meshes, so that a surface plugin without meshes still runs.
  virtual CoarseMeshes DoMakeCoarseMeshes(const PartSpec& inner, const PartSpec& outer) const;
  // Default: no lead-in.
  virtual LeadIn DoMakeLeadIn(const PartSpec& inner, const PartSpec& outer) const;
  // Default: an empty mesh (no render mesh for this surface type).
  virtual RenderMesh DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const;
};

}  // namespace fitfeel
