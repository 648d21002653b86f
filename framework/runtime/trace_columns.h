#pragma once

#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/runtime/tick_record.h"

namespace fitfeel {

// The columns of trace.csv, defined once for every reader of a run's records: the CSV writer
// (TraceHeader, AppendTraceRow) formats these values, and the Python module hands the same
// columns over as arrays, so the two cannot disagree on a name, an order or a unit.

// How a column's value is written as text.
enum class TraceColumnKind {
  kNumber,  // the shortest decimal that reads back as the same double
  kFlag,    // 1 or 0
  kStage,   // the stage's name (ToString(StageId)); the value is the StageId
};

struct TraceColumn {
  std::string name;  // with its unit: depth_mm, fy_N, offset_um, ...
  TraceColumnKind kind = TraceColumnKind::kNumber;
};

// Columns of a scene with `features` named features (axial_<name>_N each, after the others) and,
// for a screw scene, the joint's columns last. Their names joined by commas are TraceHeader's.
FITFEEL_API std::vector<TraceColumn> TraceColumns(const std::vector<std::string>& features,
                                                  bool screw);

// How many values TraceValues writes for `features` features.
FITFEEL_API int TraceColumnCount(int features, bool screw);

// One record's values in TraceColumns' order and units (TraceColumnCount of them into `values`):
// exactly the numbers trace.csv prints, before formatting.
FITFEEL_API void TraceValues(const TickRecord& record, int features, bool screw, double* values);

}  // namespace fitfeel
