#pragma once

#include <cstddef>
#include <string>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/skin_model_shape.h"
#include "framework/plot/figure.h"
#include "framework/plot/run_record.h"

namespace fitfeel::plot {

// The constrained stage's depth range of a trace, mm.
struct DepthRange {
  double min = 0.0;
  double max = 0.0;
};
FITFEEL_API DepthRange ConstrainedDepthRange(const ConstrainedTrace& trace);

// Index of the trace row whose depth is nearest `depth_mm`. Throws UserError when the depth lies
// outside the run's constrained depth range (the run never reached it, so it has no force there).
FITFEEL_API std::size_t RowAtDepth(const ConstrainedTrace& trace, double depth_mm);

// What a contact-pressure picture shows (paper Fig. 11): the interference delta(P_ij) of every
// cell of the inner part's grid at one depth, turned into pressure by the law's pressure per unit
// interference, and the resultant forces the run recorded at that depth.
struct PressureMapData {
  std::string scenario;
  std::string law;
  double depth_mm = 0.0;
  SurfaceGrid grid;                        // the inner part's grid
  Eigen::VectorXd interference;            // delta per cell, m (>= 0)
  double pressure_per_interference = 0.0;  // Pa/m
  // The recorded force, as it acts on the inner part in the outer part's frame (the analyzer's,
  // AnalyzerPose): the run's own where the inner part moves, reflected in z where the outer part
  // moves, so that its direction is read on the inner part's map.
  double fx_N = 0.0, fy_N = 0.0, fz_N = 0.0;
  double force_depth_mm = 0.0;  // depth of the tick the forces come from (nearest to depth_mm)
  std::string pose_note;        // how the pose was taken, when not from the run's pose columns
};

// Pressure map in MPa over axial position (mm) x direction angle (degrees), with the axial and
// radial resultants in the subtitle and the radial force's direction drawn across the map.
// Throws UserError for inconsistent sizes or a negative pressure coefficient.
FITFEEL_API HeatMapChart MakePressureChart(const PressureMapData& data);

}  // namespace fitfeel::plot
