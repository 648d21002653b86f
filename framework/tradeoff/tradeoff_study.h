#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/model/discretizer.h"
#include "framework/scenario/scene.h"

namespace fitfeel::tradeoff {

// Speed against accuracy of a scene over a ladder of grid resolutions (README.md).
//
// A grid of other rows x columns draws other skin model shapes from the same seed (the
// generator snaps its sampling sections to rows and bounds its harmonics by the columns, and its
// rejection loop consumes a varying number of draws), so one seed per grid would compare two
// different parts, not two discretisations of one part. The study therefore runs every grid with
// the same several seeds and compares statistics over seeds: the mean axial resistance (with its
// seed-to-seed spread) and the seed-averaged axial trace against the finest grid's, whose
// remaining sampling noise is reported beside it.

struct TradeoffSettings {
  std::vector<Resolution> ladder;  // grids to run, any order; auto: the surface type's choice
  int seeds = 10;                  // runs per grid, with seeds run.seed, run.seed + 1, ...
  std::optional<double> duration;  // overrides run.duration, s
  // Run grids whose estimated preparation or trace exceeds the loader's large-scene thresholds,
  // and ladders whose traces held for the comparison exceed kLargeSceneBytes (--allow-large).
  bool allow_large = false;
  // Called with one line per finished grid (for a progress display); may be empty.
  std::function<void(const std::string&)> progress;
};

// What one run leaves for the study.
struct RunSample {
  int inner_rows = 0, inner_columns = 0, outer_rows = 0, outer_columns = 0;
  double prepare_seconds = 0.0;
  double tick_p50_us = 0.0;  // per-tick compute time of the run, us
  double tick_p99_us = 0.0;
  // Axial resistance fy of each tick, N; NaN where the tick was not in the constrained stage.
  std::vector<double> fy;
};

// One grid's line of the study.
struct GridRow {
  std::string label;  // "40x360", "auto = 24x96" ...
  int inner_rows = 0, inner_columns = 0, outer_rows = 0, outer_columns = 0;
  long inner_cells = 0, outer_cells = 0;
  int seeds = 0;
  double prepare_seconds = 0.0;  // median over the seeds
  double tick_p50_us = 0.0;      // median over the seeds of each run's p50
  double tick_p99_us = 0.0;      // median over the seeds of each run's p99
  // Mean over the seeds of each run's mean |fy| over its constrained ticks, the sample standard
  // deviation of those means (seed-to-seed spread) and the standard error of their mean, N.
  double mean_axial_N = 0.0;
  double sd_axial_N = 0.0;
  double se_axial_N = 0.0;
  double bias_N = 0.0;  // mean_axial_N minus the reference's
  // Standard error of bias_N from the paired per-seed differences of the run means, N.
  double bias_se_N = 0.0;
  std::vector<double> run_means_N;  // each seed's mean |fy|, in seed order
  // The seed-averaged trace against the reference's, over the ticks constrained in every run of
  // both grids: RMS and max of |fy_mean - fy_ref_mean|, N, and relative to the reference's
  // mean_axial_N. noise_rms_N is the RMS over those ticks of the standard error of that
  // difference, from the paired per-seed differences (seed sampling alone): an error near it is
  // not resolved by this many seeds.
  double rms_error_N = 0.0;
  double max_error_N = 0.0;
  double rms_error_rel = 0.0;
  double max_error_rel = 0.0;
  double noise_rms_N = 0.0;
  long compared_ticks = 0;
  bool reference = false;
};

// Builds the rows from every grid's runs (one vector of samples per grid, the seeds in the same
// order in each): sorts by cell count, takes the finest as the reference, computes the
// statistics. Throws UserError when a grid has no run, the seeds differ in number, or no tick is
// constrained in every run (nothing to compare).
FITFEEL_API std::vector<GridRow> Summarize(const std::vector<std::string>& labels,
                                           const std::vector<std::vector<RunSample>>& runs);

// Admits the study as the loader admits a scene (LargeCostRefusal), before anything runs: every
// grid of the ladder prepared on `scene` (its resolution replaced), each run's trace at the
// study's duration, and the axial traces the comparison holds (8 B per tick of every run).
// Throws UserError naming the option to change (--resolutions, --duration or --seeds) with the
// estimate, unless settings.allow_large; UserError too for a grid the surface type cannot
// discretize.
FITFEEL_API void AdmitLadder(const Scene& scene, const TradeoffSettings& settings);

// The grids of `ladder` that `scene` can be discretized on and, unless `allow_large`, prepares
// within the large-scene thresholds (for a ladder the user did not choose: the default one); each
// grid left out is described in `left_out`, why included ("160x1440, over the large-scene
// thresholds (4.61e+05 cells, ...; --allow-large keeps it)").
FITFEEL_API std::vector<Resolution> AdmittedGrids(const Scene& scene,
                                                  const std::vector<Resolution>& ladder,
                                                  bool allow_large,
                                                  std::vector<std::string>* left_out);

// Runs the scene at every grid with every seed (virtual clock, trace kept in a private temporary
// folder) and summarizes, after AdmitLadder on the first scene `load` gives. `load` returns a freshly loaded scene (a run consumes its device).
// An `auto` grid that resolves to a grid of the ladder is reported once, under both names.
FITFEEL_API std::vector<GridRow> RunTradeoff(const std::function<Scene()>& load,
                                             const TradeoffSettings& settings);

// The CSV of the rows (header line with units, one line per grid, coarse to fine).
FITFEEL_API std::string TradeoffCsv(const std::vector<GridRow>& rows);

// Reads the fy column of a trace.csv text, NaN on ticks outside the constrained stage. Throws
// std::runtime_error when the text lacks the columns (the runtime's format changed).
FITFEEL_API std::vector<double> ConstrainedFy(const std::string& trace_csv);
// The same from a stream, read a line at a time (a run's trace file, which may be large).
FITFEEL_API std::vector<double> ConstrainedFy(std::istream& trace_csv);

}  // namespace fitfeel::tradeoff
