#pragma once

#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/surface_type.h"

namespace fitfeel::thread {

// fitfeel.surface.thread: ISO 68-1 threads screwed together (docs/threads.md): helicoid flanks
// with pitch-diameter, pitch and flank-angle deviations, their Winkler contact with friction
// along the helix, and the bearing face of a tightened joint in series (VDI 2230). Its
// constrained motion is a screw: a scene of it runs on the screw stage, never beside other
// features.
class ThreadSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override { return {}; }
  // The limits of the pitch deviation and of each flank's half-angle deviation; a half-angle
  // deviation above 5 deg is another thread, not a deviation of this one (the pitch deviation's
  // limit, P/10, depends on the geometry and is checked there).
  std::vector<DeclaredCharacteristic> DoDeclaredCharacteristics() const override {
    return {{"pitch_error", Dimension::kLength, std::numeric_limits<double>::infinity()},
            {"flank_angle_error", Dimension::kAngle, 5.0 * std::numbers::pi / 180.0}};
  }
  std::vector<std::string> DoLawNames() const override { return {"flank"}; }
  // Turns about its axis (with the advance the lead couples to it): the summary's torque.
  bool DoRotational() const override { return true; }
  std::shared_ptr<const SurfaceOptions> DoParseOptions(const ConfigNode& options) const override;

  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& geometry) const override;
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override;
  // The joint against the bolt: the nut meets the plates within the bolt's length, and VDI
  // 2230's bodies exist (hole below the bearing diameter and the plates' width).
  void DoCheckModel(const PartSpec& inner, const PartSpec& outer, const ModelSettings& model,
                    const ConfigNode& model_node) const override;
  // The engaged thread's stiffness, the axial play, and with a joint its compliances, preload per
  // turn, VDI 2230's tightening torque per preload and permissible assembly preload.
  std::vector<std::string> DoDescribeModel(const PartSpec& inner, const PartSpec& outer,
                                           const ModelSettings& model) const override;
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override;
  std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const override;
  RenderMesh DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const override;
};

}  // namespace fitfeel::thread
