#include "framework/scenario/scene_summary.h"

#include "framework/model/measured_surface.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "framework/core/quantity.h"
#include "framework/iso965/iso965.h"
#include "framework/safety/force_mapping.h"

namespace fitfeel {
namespace {

std::string Number(double value, const char* format = "%g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

std::string Length(double metres) { return FormatQuantity(metres, Dimension::kLength); }

// Deviations in um, as ISO 286 tables print them.
// Adding 0.0 turns a table's -0 (an H hole's EI) into +0.
std::string Micrometres(double metres) { return Number(metres * 1e6 + 0.0, "%+.4g"); }

// The perceptual force mapping the scene's device renders with, with a few scene forces (from a
// clearance fit's friction to a press fit's) and what the device gives for them; empty for a
// linear one.
std::string DescribeMapping(const Scene& scene, const DeviceSpec& spec) {
  const SafetySettings settings = scene.safety ? scene.safety->settings : SafetySettings{};
  if (settings.force_mapping.value_or(spec.force_mapping) != ForceMappingKind::kPerceptual) {
    return "";
  }
  const ForceMapping map = MakeForceMapping(settings, spec, settings.force_scale);
  // Scene forces as given; device forces to the 0.1 % a hand's 7 % Weber fraction leaves unseen.
  auto scene_force = [](double newtons) { return Number(newtons, "%.6g") + " N"; };
  auto device_force = [](double newtons) { return Number(newtons, "%.4g") + " N"; };
  std::string out = "mapping      perceptual: knee " + scene_force(map.knee()) + ", exponent " +
                    Number(map.exponent(), "%.4g") + ", scene top " + scene_force(map.scene_top()) +
                    " -> device top " + device_force(map.device_top()) + "\n";
  out += "             ";
  for (double f : {0.3, 10.0, 1e3, 10e3}) {
    out += std::string(f == 0.3 ? "" : ", ") + scene_force(f) + " -> " + device_force(map.Map(f));
  }
  return out + "\n";
}

std::string DescribePart(const PartSpec& part, bool moving) {
  const std::string indent = "             ";
  std::string out = "  " + std::string(part.role == Role::kInner ? "inner " : "outer ") + "     " +
                    part.name + (moving ? " (moving)" : "") + "\n";
  const SizeSpec& size = part.size;
  if (size.pitch > 0.0) {
    // A thread's deviations are its pitch diameter's (ISO 965-1).
    const double d2 = iso965::BasicPitchDiameter(size.nominal, size.pitch);
    out += indent + "size " + size.iso_code + ": pitch diameter deviations " +
           Micrometres(size.lower_deviation) + " .. " + Micrometres(size.upper_deviation) +
           " um (d2 " + Number((d2 + size.lower_deviation) * 1e3, "%.4f") + " .. " +
           Number((d2 + size.upper_deviation) * 1e3, "%.4f") + " mm)\n";
  } else {
    out += indent + "size " + Length(size.nominal) +
           (size.iso_code.empty() ? "" : " " + size.iso_code) + ": deviations " +
           Micrometres(size.lower_deviation) + " .. " + Micrometres(size.upper_deviation) +
           " um (limits " + Number((size.nominal + size.lower_deviation) * 1e3, "%.4f") + " .. " +
           Number((size.nominal + size.upper_deviation) * 1e3, "%.4f") + " mm)\n";
  }
  if (part.geometry) out += indent + "geometry " + part.geometry->Describe() + "\n";
  std::string form;
  for (const auto& [characteristic, tolerance] : part.form.tolerance) {
    form += (form.empty() ? "" : ", ") + ToString(characteristic) + " " + Length(tolerance);
  }
  out += indent + "form " + (form.empty() ? "none given (ideal form)" : form) + "\n";
  const TextureSpec& texture = part.texture;
  if (texture.waviness == 0.0 && texture.ra == 0.0 && texture.rz == 0.0) {
    out += indent + "texture none given (smooth)\n";
  } else {
    out += indent + "texture waviness " + Length(texture.waviness) + ", Ra " + Length(texture.ra) +
           ", Rz " + Length(texture.rz) + "\n";
  }
  const Material& material = part.material;
  out += indent + "material " + (material.name.empty() ? "" : material.name + ", ") + "E " +
         FormatQuantity(material.youngs_modulus, Dimension::kPressure) + ", nu " +
         Number(material.poisson) + "\n";
  if (part.measured) {
    const MeasuredSurface& m = *part.measured;
    out += indent + "measured " + MeasurementKindName(m.kind) + " " + m.file.string() + ": " +
           std::to_string(m.value.size()) + " samples" +
           (m.traces > 0 ? " in " + std::to_string(m.traces) + " traces" : std::string()) +
           " (drawn parts' size and form are the drawing it is checked against)\n";
  }
  return out;
}

std::string DescribeModel(const ModelSettings& model) {
  return "law " + model.law + ", friction " + Number(model.friction) + " (static " +
         Number(model.static_friction) + ", breakaway " +
         FormatQuantity(model.breakaway_displacement, Dimension::kLength) + ")" +
         ", contact stiffness " +
         (model.contact_stiffness > 0.0
              ? FormatQuantity(model.contact_stiffness, Dimension::kStiffness)
              : std::string("auto")) +
         ", resolution " +
         (model.resolution.is_auto() ? std::string("auto")
                                     : std::to_string(model.resolution.rows) + " x " +
                                           std::to_string(model.resolution.columns)) +
         ", texture " + TextureModeName(model.texture) + ", depth step " +
         (model.depth_step > 0.0 ? Length(model.depth_step) : "auto");
}

// Where a feature of a several-feature scene lies, as the loader understood it.
std::string DescribePlacement(const MatingFeature& f, bool datum) {
  if (datum) return "the datum: its axis is the joint's";
  const FeaturePlacement& p = f.placement;
  std::string out = "at x " + Length(p.at.x()) + ", z " + Length(p.at.y());
  if (p.angle != 0.0) out += ", turned " + FormatQuantity(p.angle, Dimension::kAngle);
  if (p.engages_after > 0.0) out += ", engages after " + Length(p.engages_after);
  if (p.inner_position > 0.0) {
    out += ", position " + f.inner.name + " " + Length(p.inner_position);
  }
  if (p.outer_position > 0.0) {
    out += ", position " + f.outer.name + " " + Length(p.outer_position);
  }
  return out;
}

}  // namespace

std::string DescribeScene(const Scene& scene) {
  std::string out = "scenario     " + scene.name + " (" + scene.file.string() + ")\n";
  if (!scene.description.empty()) out += "description  " + scene.description + "\n";
  if (scene.features.empty()) {
    out += "surface      " + scene.surface_id + "\n";
    out += "parts\n";
    out += DescribePart(scene.inner, scene.moving == Role::kInner);
    out += DescribePart(scene.outer, scene.moving == Role::kOuter);
    out += "model        " + DescribeModel(scene.model) + "\n";
    if (scene.surface) {
      for (const std::string& line :
           scene.surface->DescribeModel(scene.inner, scene.outer, scene.model)) {
        out += "             " + line + "\n";
      }
    }
  } else {
    out += "bodies       " + scene.fixed_body + " (fixed), " + scene.moving_body + " (moving)\n";
    for (std::size_t i = 0; i < scene.features.size(); ++i) {
      const MatingFeature& f = scene.features[i];
      out += "feature      " + f.name + ": " + f.surface_id + ", " + DescribePlacement(f, i == 0) +
             "\n";
      out += DescribePart(f.inner, f.moving == Role::kInner);
      out += DescribePart(f.outer, f.moving == Role::kOuter);
      out += "  model      " + DescribeModel(f.model) + "\n";
    }
    const PartMotionSettings& motion = scene.part_motion;
    out += "rotation     " +
           std::string(motion.rotation == RotationMotion::kFree ? "free" : "held") +
           " about the axis";
    for (const TorquePoint& point : motion.torque) {
      out += (&point == &motion.torque.front() ? ", torque " : ", ") +
             FormatQuantity(point.torque, Dimension::kTorque) + " at " +
             FormatQuantity(point.time, Dimension::kTime);
    }
    out += "\n";
  }
  out += "device       " + scene.device_id;
  if (scene.device) {
    const DeviceSpec spec = scene.device->spec();
    if (!spec.model.empty()) out += " (" + spec.model + ")";
    out += "\n" + DescribeMapping(scene, spec);
  } else {
    out += "\n";
  }
  const RunSettings& run = scene.run;
  const double ticks = std::floor(run.duration * run.rate + 0.5);
  std::string outputs;
  if (run.write_trace) outputs += "trace";
  if (run.write_summary) outputs += std::string(outputs.empty() ? "" : ", ") + "summary";
  if (run.write_recording) outputs += std::string(outputs.empty() ? "" : ", ") + "recording";
  out += "run          " + FormatQuantity(run.rate, Dimension::kFrequency) + " for " +
         FormatQuantity(run.duration, Dimension::kTime) + " (" + Number(ticks, "%.0f") +
         " ticks), seed " + std::to_string(run.seed) + ", clock " +
         (run.clock == ClockMode::kVirtual ? "virtual" : "realtime") + ", outputs " +
         (outputs.empty() ? "none" : outputs) + "\n";
  // The loader's estimate (docs/scenario-format.md, cost admission), before anything is drawn.
  const SceneCost& cost = scene.cost;
  out += "cost         " + std::to_string(cost.inner_cells) + " + " +
         std::to_string(cost.outer_cells) + " cells, " + Number(cost.depth_steps, "%.0f") +
         " depth steps: about " + Number(cost.prepare_bytes / (1 << 20), "%.3g") + " MiB and " +
         Number(cost.prepare_seconds, "%.3g") + " s to prepare" +
         (cost.law_prepare_seconds > 0.0
              ? " (" + Number(cost.law_prepare_seconds, "%.3g") + " s of it the law's, at worst)"
              : std::string()) +
         ", " + Number(cost.run_bytes / (1 << 20), "%.3g") + " MiB for the run\n";
  // What the run writes (docs/scenario-format.md, "Output size"), estimated before it runs.
  const double gib = 1024.0 * 1024.0 * 1024.0;
  out +=
      "output       " +
      (cost.output_bytes > 0.0
           ? "about " +
                 (cost.output_bytes < gib ? Number(cost.output_bytes / (1 << 20), "%.3g") + " MiB"
                                          : Number(cost.output_bytes / gib, "%.3g") + " GiB") +
                 " (" + DescribeOutputs(cost) + ")"
           : DescribeOutputs(cost)) +
      "\n";
  return out;
}

}  // namespace fitfeel
