#include "surfaces/thread/thread_surface.h"

#include <cmath>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "surfaces/thread/joint_model.h"
#include "surfaces/thread/thread_contact_analyzer.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_law.h"
#include "surfaces/thread/thread_options.h"
#include "surfaces/thread/thread_shape.h"

namespace fitfeel::thread {

std::unique_ptr<Discretizer> ThreadSurface::DoMakeDiscretizer() const {
  return std::make_unique<HelicoidDiscretizer>();
}

std::unique_ptr<VariationGenerator> ThreadSurface::DoMakeVariationGenerator() const {
  return std::make_unique<HelicoidVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> ThreadSurface::DoMakeContactAnalyzer() const {
  return std::make_unique<ThreadContactAnalyzer>();
}

std::unique_ptr<ResistanceLaw> ThreadSurface::DoMakeLaw(std::string_view) const {
  return std::make_unique<ThreadLaw>();
}

std::shared_ptr<const SurfaceOptions> ThreadSurface::DoParseOptions(
    const ConfigNode& options) const {
  return ParseThreadOptions(options);
}

std::shared_ptr<const Geometry> ThreadSurface::DoParseGeometry(const PartSpec& part,
                                                               const ConfigNode& geometry) const {
  return ParseHelicoidGeometry(part, geometry);
}

void ThreadSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                                const ConfigNode& pair_node) const {
  const HelicoidGeometry& a = HelicoidGeometryOf(inner);
  const HelicoidGeometry& b = HelicoidGeometryOf(outer);
  auto differ = [](double x, double y) { return std::abs(x - y) > 1e-12 * std::max(1.0, x); };
  // A bolt screws into a nut of its own nominal thread only.
  if (differ(a.diameter(), b.diameter()) || differ(a.pitch(), b.pitch()) ||
      differ(a.flank_angle(), b.flank_angle())) {
    pair_node.Fail("the same nominal diameter, pitch and flank angle on '" + inner.name +
                       "' and '" + outer.name + "'",
                   a.Describe() + " and " + b.Describe());
  }
}

void ThreadSurface::DoCheckModel(const PartSpec& inner, const PartSpec& outer,
                                 const ModelSettings& model, const ConfigNode& model_node) const {
  const JointOptions joint = ThreadOptionsOf(model).joint;
  if (!joint.present()) return;
  const ConfigNode node = model_node.Child("options").Child("joint");
  const HelicoidGeometry& bolt = HelicoidGeometryOf(inner);
  if (joint.seat + joint.clamp_length() > bolt.length() + 1e-12) {
    node.Child("seat").Fail(
        "a run-down that leaves the plates on the bolt: seat + plates at most the bolt's length " +
            FormatQuantity(bolt.length(), Dimension::kLength),
        node.Child("seat").Describe() + " + " +
            FormatQuantity(joint.clamp_length(), Dimension::kLength) + " of plates");
  }
  try {
    MakeJointModel(inner, outer, joint);
  } catch (const UserError& e) {
    node.Fail("a joint VDI 2230 can model (bearing diameter, hole and plate width in order)",
              e.what());
  }
}

std::vector<CharacteristicCheck> ThreadSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  return EvaluateHelicoidCharacteristics(part, sms);
}

RenderMesh ThreadSurface::DoMakeRenderMesh(const PartSpec& part, const SurfaceGrid& grid) const {
  return HelicoidRenderMesh(part, grid);
}

}  // namespace fitfeel::thread
