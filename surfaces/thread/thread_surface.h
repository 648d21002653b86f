#pragma once

#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/surface_type.h"

namespace fitfeel::thread {

// The message every refusal of this surface type carries.
inline constexpr const char* kLimitation =
    "threaded (helicoid) mating has no resistance law yet: the stub parses and validates the "
    "helicoid, discretizes both flanks and generates pitch-diameter, pitch and flank-angle "
    "deviations, but the contact of a screw advancing by rotation (the constrained motion couples "
    "turn and advance; the flank load has axial, radial and tangential parts) is not modelled";

// fitfeel.surface.thread: a stub that registers, validates and discretizes, and refuses to
// render forces (renders_forces() is false; analyzers and laws throw UnsupportedError).
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
  std::vector<std::string> DoLawNames() const override { return {}; }
  bool DoRendersForces() const override { return false; }
  std::string DoLimitation() const override { return kLimitation; }
  bool DoRotational() const override { return true; }

  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override;
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override;
  // Throws UnsupportedError with kLimitation.
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override;

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& geometry) const override;
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override;
  // Throws UnsupportedError with kLimitation.
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override;
  std::vector<CharacteristicCheck> DoEvaluateCharacteristics(
      const PartSpec& part, const SkinModelShape& sms) const override;
};

}  // namespace fitfeel::thread
