#include "surfaces/thread/thread_surface.h"

#include <cmath>
#include <cstdio>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/joint_model.h"
#include "surfaces/thread/thread_contact_analyzer.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_law.h"
#include "surfaces/thread/thread_options.h"
#include "surfaces/thread/thread_shape.h"
#include "surfaces/thread/thread_torque.h"

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

std::vector<std::string> ThreadSurface::DoDescribeModel(const PartSpec& inner,
                                                        const PartSpec& outer,
                                                        const ModelSettings& model) const {
  const HelicoidGeometry& bolt = HelicoidGeometryOf(inner);
  const JointOptions joint = ThreadOptionsOf(model).joint;
  const JointModel m = MakeJointModel(inner, outer, joint);
  auto number = [](double v, const char* format) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return std::string(buffer);
  };
  const double flank =
      model.contact_stiffness > 0.0 ? model.contact_stiffness : 1.0 / m.engaged_thread_compliance;
  // The pitch diameters' clearance leaves an axial play of clearance x tan(alpha/2).
  const double play_min =
      (outer.size.lower_deviation - inner.size.upper_deviation) * std::tan(bolt.half_angle());
  const double play_max =
      (outer.size.upper_deviation - inner.size.lower_deviation) * std::tan(bolt.half_angle());
  std::vector<std::string> lines = {
      "thread: engaged thread " + number(flank * 1e-9, "%.3g") + " kN/um" +
      (model.contact_stiffness > 0.0 ? "" : " (VDI 2230 delta_G + delta_M)") + ", axial play " +
      number(play_min * 1e6, "%.1f") + " .. " + number(play_max * 1e6, "%.1f") + " um"};
  if (!joint.present()) return lines;
  const double lead = bolt.pitch();
  lines.push_back("joint: clamp " + FormatQuantity(joint.clamp_length(), Dimension::kLength) +
                  ", bearing d_W " + FormatQuantity(m.bearing_diameter, Dimension::kLength) +
                  ", hole d_h " + FormatQuantity(m.hole_diameter, Dimension::kLength) +
                  ", seat after " + FormatQuantity(joint.seat, Dimension::kLength) +
                  " of run-down");
  lines.push_back("joint: delta_S " + number(m.bolt_compliance * 1e9, "%.4g") + " um/kN, delta_P " +
                  number(m.plate_compliance * 1e9, "%.4g") + " um/kN: preload " +
                  number(lead / (m.bolt_compliance + m.plate_compliance) * 1e-3, "%.4g") +
                  " kN per turn past snug");
  const double per_kn =
      VdiTighteningTorque(bolt.diameter(), lead, 1e3, model.friction, m.bearing_diameter,
                          m.hole_diameter, joint.bearing_friction);
  std::string vdi = "joint: VDI 2230 tightening torque " + number(per_kn, "%.3g") +
                    " N*m per kN of preload (mu_G " + number(model.friction, "%g") + ", mu_K " +
                    number(joint.bearing_friction, "%g") + ")";
  if (m.yield_strength > 0.0) {
    const double allowed =
        PermissibleAssemblyPreload(bolt.diameter(), lead, m.yield_strength, model.friction);
    vdi += "; class " + joint.property_class + ": F_M,zul " + number(allowed * 1e-3, "%.3g") +
           " kN at 90 % of R_p0.2 (" + number(allowed * per_kn * 1e-3, "%.3g") + " N*m)";
  }
  lines.push_back(vdi);
  return lines;
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
