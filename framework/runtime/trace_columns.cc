#include "framework/runtime/trace_columns.h"

#include <cmath>

namespace fitfeel {
namespace {

using Kind = TraceColumnKind;

// The output contract's columns first, in the order TraceValues writes them; columns are only
// ever appended, so readers that index by position keep working. fy is the axial resistance (the
// paper's y, along the mating axis), fx and fz the radial components; all on the moving part, in
// physical newtons. The dev_* columns are what the safety chain sent to the device (device
// newtons: scaled, coupled, limited). x_mm and z_mm are the device's position; offset_x_um and
// offset_z_um the pose's, which differ where the constrained stage settles the part
// quasi-statically under a radial load (DeviceState::load). elastic_utilisation is the largest
// equivalent stress over the yield strength (DIN 7190), yielding 1 where it exceeds 1 (the elastic
// model no longer holds there). device_fault is 1 where the device state was not finite or beyond
// physical bounds: the last sane state was held and zero force sent (summary.json: device_faults).
// prepare_held_mm is how far the part was past a progressive prepare's frontier, its contact the
// frontier's (0: not held; summary.json: held_for_prepare).
const TraceColumn kBase[] = {
    {"t_s", Kind::kNumber},
    {"stage", Kind::kStage},
    {"depth_mm", Kind::kNumber},
    {"fx_N", Kind::kNumber},
    {"fy_N", Kind::kNumber},
    {"fz_N", Kind::kNumber},
    {"tick_us", Kind::kNumber},
    {"x_mm", Kind::kNumber},
    {"y_mm", Kind::kNumber},
    {"z_mm", Kind::kNumber},
    {"angle_rad", Kind::kNumber},
    {"tx_Nm", Kind::kNumber},
    {"ty_Nm", Kind::kNumber},
    {"tz_Nm", Kind::kNumber},
    {"engaged", Kind::kFlag},
    {"interference", Kind::kFlag},
    {"offset_um", Kind::kNumber},
    {"assembly_extent_um", Kind::kNumber},
    {"penetration_um", Kind::kNumber},
    {"max_interference_um", Kind::kNumber},
    {"stiffness_N_per_um", Kind::kNumber},
    {"guard_fault", Kind::kFlag},
    {"dev_fx_N", Kind::kNumber},
    {"dev_fy_N", Kind::kNumber},
    {"dev_fz_N", Kind::kNumber},
    {"dev_tx_Nm", Kind::kNumber},
    {"dev_ty_Nm", Kind::kNumber},
    {"dev_tz_Nm", Kind::kNumber},
    {"offset_x_um", Kind::kNumber},
    {"offset_z_um", Kind::kNumber},
    {"elastic_utilisation", Kind::kNumber},
    {"yielding", Kind::kFlag},
    {"device_fault", Kind::kFlag},
    {"prepare_held_mm", Kind::kNumber},
};
constexpr int kBaseCount = static_cast<int>(std::size(kBase));

// A screw's joint: preload, the torque turning the part against the contact and its shares at the
// flanks and at the bearing face, and 1 once the bearing face has met.
const TraceColumn kScrew[] = {
    {"preload_N", Kind::kNumber},
    {"torque_Nm", Kind::kNumber},
    {"thread_torque_Nm", Kind::kNumber},
    {"head_torque_Nm", Kind::kNumber},
    {"seated", Kind::kFlag},
};
constexpr int kScrewCount = static_cast<int>(std::size(kScrew));

double Flag(bool b) { return b ? 1.0 : 0.0; }

}  // namespace

std::vector<TraceColumn> TraceColumns(const std::vector<std::string>& features, bool screw) {
  std::vector<TraceColumn> columns(std::begin(kBase), std::end(kBase));
  for (const std::string& name : features)
    columns.push_back({"axial_" + name + "_N", Kind::kNumber});
  if (screw) columns.insert(columns.end(), std::begin(kScrew), std::end(kScrew));
  return columns;
}

int TraceColumnCount(int features, bool screw) {
  return kBaseCount + features + (screw ? kScrewCount : 0);
}

void TraceValues(const TickRecord& r, int features, bool screw, double* v) {
  *v++ = r.time;
  *v++ = static_cast<double>(static_cast<int>(r.stage));
  *v++ = r.pose.depth * 1e3;
  for (int i = 0; i < 3; ++i) *v++ = r.wrench.force[i];
  // Compute time to 0.01 us: finer digits are clock noise and would only bloat the file.
  *v++ = std::round(r.compute_us * 100.0) / 100.0;
  for (int i = 0; i < 3; ++i) *v++ = r.position[i] * 1e3;
  *v++ = r.pose.angle;
  for (int i = 0; i < 3; ++i) *v++ = r.wrench.torque[i];
  *v++ = Flag(r.contact.engaged);
  *v++ = Flag(r.contact.interference);
  *v++ = r.contact.offset_distance * 1e6;
  *v++ = r.contact.assembly_extent * 1e6;
  *v++ = r.contact.penetration * 1e6;
  *v++ = r.contact.max_interference * 1e6;
  *v++ = r.stiffness * 1e-6;
  *v++ = Flag(r.guard_fault);
  for (int i = 0; i < 3; ++i) *v++ = r.device_wrench.force[i];
  for (int i = 0; i < 3; ++i) *v++ = r.device_wrench.torque[i];
  *v++ = r.pose.offset.x() * 1e6;
  *v++ = r.pose.offset.y() * 1e6;
  *v++ = r.elastic.utilisation;
  *v++ = Flag(r.elastic.utilisation > 1.0);
  *v++ = Flag(r.device_fault);
  *v++ = r.contact.held_depth * 1e3;
  // A record holds at most kMaxJointFeatures features' forces; columns past them read 0.
  for (int i = 0; i < features; ++i) *v++ = i < kMaxJointFeatures ? r.feature_axial[i] : 0.0;
  if (!screw) return;
  *v++ = r.screw.preload;
  *v++ = r.screw.torque;
  *v++ = r.screw.thread_torque;
  *v++ = r.screw.head_torque;
  *v++ = Flag(r.screw.seated);
}

}  // namespace fitfeel
