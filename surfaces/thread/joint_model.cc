#include "surfaces/thread/joint_model.h"

#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/fastener_tables.h"
#include "surfaces/thread/property_class.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_torque.h"

namespace fitfeel::thread {

JointModel MakeJointModel(const PartSpec& bolt, const PartSpec& nut, const JointOptions& joint) {
  const HelicoidGeometry& g = HelicoidGeometryOf(bolt);
  const double d = g.diameter(), p = g.pitch();
  // Without a joint only the flank pair's terms are read, which no clamp length enters.
  ThroughBolt through{d,
                      p,
                      joint.present() ? joint.clamp_length() : d,
                      {},
                      bolt.material.youngs_modulus,
                      nut.material.youngs_modulus};
  if (joint.shank > 0.0) through.shank.push_back({joint.shank, d});
  const BoltResilience resilience = ThroughBoltResilience(through);
  JointModel model;
  model.engaged_thread_compliance = resilience.thread_pair();
  model.stress_area = StressArea(d, p);
  model.polar_modulus = StressSectionModulus(d, p);
  if (!joint.present()) return model;
  model.bearing_diameter = joint.bearing_diameter > 0.0 ? joint.bearing_diameter
                                                        : MetricFastenerOf(d).nut_bearing_diameter;
  model.hole_diameter = joint.hole_diameter > 0.0
                            ? joint.hole_diameter
                            : MetricFastenerOf(d).clearance_hole(ClearanceSeries::kMedium);
  const ClampedParts plates{
      model.bearing_diameter, model.hole_diameter, joint.clamp_length(), joint.plate_outer_diameter,
      joint.plate_modulus > 0.0 ? joint.plate_modulus : bolt.material.youngs_modulus};
  model.plate_compliance = ThroughBoltPlateResilience(plates).resilience;
  model.bolt_compliance = resilience.total();
  model.clamp_stiffness =
      joint.stiffness > 0.0 ? joint.stiffness
                            : 1.0 / (resilience.series_with_thread_pair() + model.plate_compliance);
  // The uniform-pressure annulus's torque per unit force and friction is its friction radius.
  model.bearing_radius =
      UniformAnnulusTorqueRatio(model.bearing_diameter, model.hole_diameter, 1.0);
  if (!joint.property_class.empty()) {
    model.yield_strength = BoltPropertyClass::Parse(joint.property_class).min_yield_strength(d);
  }
  return model;
}

}  // namespace fitfeel::thread
