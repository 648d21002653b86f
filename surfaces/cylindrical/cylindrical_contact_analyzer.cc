#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "framework/core/error.h"
#include "framework/core/least_norm.h"
#include "framework/core/number_text.h"
#include "framework/core/parallel.h"
#include "framework/core/simd_clones.h"
#include "framework/model/convex_polygon.h"
#include "framework/model/shared_prepare.h"
#include "surfaces/common/grid_rows.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/cylindrical_options.h"
#include "surfaces/cylindrical/elastic/section_contact.h"
#include "surfaces/cylindrical/fixed_lane_dot.h"

namespace fitfeel::cylindrical {
namespace {

// An automatic step never makes more rows than this (a step of 3 um on a 60 mm stroke), however
// fine the grid: a haptic hand does not resolve the difference, and the tables stay in memory.
constexpr double kAutoDepthSteps = 20000;
// Half-width of the box that bounds an assembly space whose normals do not surround the origin;
// clearances are micrometres, so one metre never binds.
constexpr double kPolygonBound = 1.0;
// Depth steps per chunk of the prepare's parallel loop: the warm starts run within a chunk, so the
// tables depend on this and not on the thread count. 32 steps: four chunks at the shipped scenes'
// 120 steps (two per thread), and a cold start (a few extra iterations) per 32 steps.
constexpr std::size_t kChunkSteps = 32;
// Steps whose per-column minima are computed together (ChunkMinima): 8 steps of 1000 columns keep
// their minima and the rows they read (about 200 kB) in a core's level-2 cache.
constexpr std::size_t kMinimaBlock = 8;

// h = min(h, vb - vs + smoothing) over n columns: ChunkMinima's inner loop, most of a fine grid's
// prepare, compiled also for AVX2 and AVX-512 (framework/core/simd_clones.h: the baseline
// x86-64 has two doubles per instruction, AVX2 four, AVX-512 eight). The minimum is written out
// as std::min's select: a clone's own optimisation attributes keep GCC from inlining std::min,
// and a call per column took the loop's vectorisation with it (10^6 cells: 1.38 s on one thread,
// where the loop vectorised took 0.33 s).
FITFEEL_SIMD_CLONES void MinOfDifference(double* __restrict h, const double* __restrict vb,
                                         const double* __restrict vs, double smoothing,
                                         std::size_t n) {
  FITFEEL_NO_FP_CONTRACT
  for (std::size_t j = 0; j < n; ++j) {
    const double d = vb[j] - vs[j] + smoothing;
    h[j] = d < h[j] ? d : h[j];
  }
}

// The same for two bore rows facing one shaft row at one step (the common case: bore rows are
// shorter than the shaft's, or straddle a boundary): h is read and written once for both.
FITFEEL_SIMD_CLONES void MinOfDifference2(double* __restrict h, const double* __restrict vb0,
                                          const double* __restrict vb1, const double* __restrict vs,
                                          double smoothing, std::size_t n) {
  FITFEEL_NO_FP_CONTRACT
  for (std::size_t j = 0; j < n; ++j) {
    const double d0 = vb0[j] - vs[j] + smoothing, d1 = vb1[j] - vs[j] + smoothing;
    const double d = d1 < d0 ? d1 : d0;  // std::min(d0, d1), as above
    h[j] = d < h[j] ? d : h[j];
  }
}

// One slice's share of Energy, column by column with d = max(0, proj - g): the energy a d^2 and,
// for the Newton step, the first and second moments a d and a [d > 0]. Sums per column, so
// that no vector width changes their order (Energy adds the columns up in a fixed one).
FITFEEL_SIMD_CLONES void EnergyMoments(double* __restrict energy, double* __restrict first,
                                       double* __restrict second, const double* __restrict proj,
                                       const double* __restrict g, const double* __restrict a,
                                       std::size_t n) {
  FITFEEL_NO_FP_CONTRACT
  for (std::size_t j = 0; j < n; ++j) {
    const double x = proj[j] - g[j];
    const double touching = x > 0.0 ? 1.0 : 0.0;  // a select, not a branch: vectorised
    const double d = x * touching;                // x > 0 or +-0 (the same in every sum)
    energy[j] += a[j] * d * d;
    first[j] += a[j] * d;
    second[j] += a[j] * touching;
  }
}

// The solve's columns' kernel for OnSolveColumns on n grid columns in blocks of `block`: the
// Fourier series of a row up to the solve's highest harmonic K = n / (2 block) (K's own term
// halved, as the solve's circulant takes it) evaluated at the centre of grid block i is the
// Dirichlet kernel, out(i) = sum_j kernel((i block - j) mod n) v(j), with
// kernel(d) = (1 + 2 sum_{q < K} cos(q a) + cos(K a)) / n at a = 2 pi (d + (block - 1) / 2) / n.
// Returned wrapped: kernel((m - j) mod n) over j = 0 .. n-1 is wrapped[n - m + j], a contiguous
// inner product. It depends on n and block alone (SolveColumnKernel shares it between prepares).
std::vector<double> MakeSolveColumnKernel(int n, int block) {
  const int highest = n / block / 2;
  // Each angle reduced exactly in integers: q a = 2 pi (q (2 d + block - 1) mod 2 n) / (2 n).
  std::vector<double> kernel(static_cast<std::size_t>(n));
  for (int d = 0; d < n; ++d) {
    const long twice = 2L * d + block - 1;
    double sum = 1.0;
    for (int q = 1; q <= highest; ++q) {
      const double angle = std::numbers::pi * static_cast<double>((q * twice) % (2L * n)) / n;
      sum += (q < highest ? 2.0 : 1.0) * std::cos(angle);
    }
    kernel[static_cast<std::size_t>(d)] = sum / n;
  }
  std::vector<double> wrapped(2 * static_cast<std::size_t>(n));
  for (int t = 0; t < 2 * n; ++t) {
    wrapped[static_cast<std::size_t>(t)] = kernel[static_cast<std::size_t>((2 * n - t) % n)];
  }
  return wrapped;
}

// MakeSolveColumnKernel's, made once for all the prepares that share `shared` (null: made here).
std::shared_ptr<const std::vector<double>> SolveColumnKernel(SharedPrepare* shared, int n,
                                                             int block) {
  if (shared == nullptr) {
    return std::make_shared<const std::vector<double>>(MakeSolveColumnKernel(n, block));
  }
  return shared->Get<std::vector<double>>(
      "cylindrical solve-column kernel:" + std::to_string(n) + ',' + std::to_string(block),
      [n, block] { return MakeSolveColumnKernel(n, block); });
}

// Each row of a part's variation v (rows x n, row-major) on the elastic solve's n / block columns,
// whose column i sits at the centre of the grid's block i: the row's Fourier series up to the
// solve's highest harmonic (`wrapped`: SolveColumnKernel's), evaluated there. Every harmonic the
// solve resolves keeps its full height; a block's mean would keep order k at sinc(pi k block / n)
// of it (0.64 at K = 60 on 360 columns), which flattens the waviness's crests that a light fit
// bears on. Returns n / block x rows.
Eigen::MatrixXd OnSolveColumns(const Eigen::VectorXd& v, int rows, int n, int block,
                               const std::vector<double>& wrapped) {
  const int solve = n / block;
  Eigen::MatrixXd out(solve, rows);
  for (int r = 0; r < rows; ++r) {
    const double* row = v.data() + static_cast<std::ptrdiff_t>(r) * n;
    for (int i = 0; i < solve; ++i) {
      out(i, r) = FixedLaneDot(wrapped.data() + (n - i * block), row, n);
    }
  }
  return out;
}

// A section solver for `section` on `columns` columns with the gap shifts of `orders`: its
// construction (the compliance matrix, its inverse and their products with the bases) depends on
// these alone, so the prepares that share `shared` copy one made once (null: made here).
RigidSectionContact SectionSolver(SharedPrepare* shared, const PressFitSection& section,
                                  int columns, const std::vector<int>& orders) {
  if (shared == nullptr) return RigidSectionContact(section, columns, orders);
  std::string key = "cylindrical section solver:";
  for (double x : {section.d1, section.d2, section.di, section.shaft.youngs_modulus,
                   section.shaft.poisson, section.hub.youngs_modulus, section.hub.poisson}) {
    AppendKey(&key, x);
  }
  // The names are in the messages a refused material throws.
  key += section.shaft.name + '\n' + section.hub.name + '\n';
  key += section.plane_strain ? "strain;" : "stress;";
  key += std::to_string(columns) + ';';
  for (int order : orders) key += std::to_string(order) + ',';
  return *shared->Get<RigidSectionContact>(
      key, [&] { return RigidSectionContact(section, columns, orders); });
}

Eigen::Vector2d Rotate(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

void CheckShape(const PartSpec& part, const SkinModelShape& sms) {
  const SurfaceGrid& g = sms.grid;
  if (g.columns < 3) {
    throw UserError("part '" + part.name + "': the assembly space needs at least 3 columns");
  }
  if (sms.variation.size() != g.size() || g.area.size() != g.size() ||
      g.column_angle.size() != g.columns) {
    throw UserError("part '" + part.name + "': skin model shape arrays do not match its grid");
  }
  if (!sms.variation.allFinite() || !(g.area.minCoeff() > 0.0)) {
    throw UserError("part '" + part.name + "': variations must be finite and cell areas positive");
  }
}

}  // namespace

void CylinderContactAnalyzer::DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                                        const PartSpec& outer, const SkinModelShape& outer_sms,
                                        const ModelSettings& settings) {
  DoPrepareStart(inner, inner_sms, outer, outer_sms, settings);
  DoFinishPrepare();
}

void CylinderContactAnalyzer::DoPrepareStart(const PartSpec& inner, const SkinModelShape& inner_sms,
                                             const PartSpec& outer, const SkinModelShape& outer_sms,
                                             const ModelSettings& settings) {
  if (inner.role != Role::kInner || outer.role != Role::kOuter) {
    throw UserError("cylindrical contact needs the inner part (shaft) first, the outer second");
  }
  CheckShape(inner, inner_sms);
  CheckShape(outer, outer_sms);
  const SurfaceGrid& gs = inner_sms.grid;
  const SurfaceGrid& gb = outer_sms.grid;
  if (gs.columns != gb.columns) {
    throw UserError("cylindrical contact needs the same number of columns on both parts (" +
                    MessageNumber(gs.columns) + " and " + MessageNumber(gb.columns) + ")");
  }
  n_ = gs.columns;
  angle_.assign(static_cast<std::size_t>(n_), 0.0);
  cos_ = sin_ = angle_;
  for (int j = 0; j < n_; ++j) {
    const double d = std::remainder(gs.column_angle[j] - gb.column_angle[j], 2 * std::numbers::pi);
    if (std::abs(d) > 1e-9) {
      throw UserError("cylindrical contact needs the same column angles on both parts");
    }
    angle_[static_cast<std::size_t>(j)] = gs.column_angle[j];
    cos_[static_cast<std::size_t>(j)] = std::cos(gs.column_angle[j]);
    sin_[static_cast<std::size_t>(j)] = std::sin(gs.column_angle[j]);
  }
  half_planes_ = HalfPlanes(angle_, kPolygonBound);
  shaft_edges_ = RowEdges(inner, gs);
  bushing_edges_ = RowEdges(outer, gb);
  shaft_rows_ = gs.rows;
  bushing_rows_ = gb.rows;
  shaft_length_ = shaft_edges_.back();
  bushing_length_ = bushing_edges_.back();
  // The shortest row of either part: the auto depth step, and the axial coupling's row length.
  double min_row = std::numeric_limits<double>::infinity();
  for (const auto* e : {&shaft_edges_, &bushing_edges_}) {
    for (std::size_t i = 1; i < e->size(); ++i) min_row = std::min(min_row, (*e)[i] - (*e)[i - 1]);
  }
  shaft_row_centre_ = gs.row_position.array() - (gs.row_position[0] - 0.5 * shaft_edges_[1]);
  if (shaft_rows_ == 1) shaft_row_centre_[0] = 0.5 * shaft_length_;
  v_shaft_ = inner_sms.variation;
  v_bushing_ = outer_sms.variation;
  shaft_area_ = gs.area;
  shaft_row_area_.assign(static_cast<std::size_t>(shaft_rows_), 0.0);
  for (int i = 0; i < shaft_rows_; ++i) {
    for (int j = 0; j < n_; ++j)
      shaft_row_area_[static_cast<std::size_t>(i)] += shaft_area_[i * n_ + j];
  }

  elastic_ = settings.law == "elastic";
  smoothing_ = settings.texture == TextureMode::kDin7190
                   ? Din7190RadialSmoothing(inner.texture, outer.texture)
                   : 0.0;
  solver_.reset();
  RigidFreedom freedom;
  double frame = 0.0;  // angle of the elastic solve's column 0
  if (elastic_) {
    for (int j = 0; j < n_; ++j) {
      if (std::abs(std::remainder(
              angle_[static_cast<std::size_t>(j)] - angle_[0] - 2.0 * std::numbers::pi * j / n_,
              2.0 * std::numbers::pi)) > 1e-9) {
        throw UserError("the elastic model needs equally spaced columns");
      }
    }
    const ElasticOptions options = CylindricalOptionsOf(settings).elastic;
    block_ = 1;
    while (n_ / block_ > options.columns || n_ % block_ != 0 || (n_ / block_) % 2 != 0) {
      ++block_;
    }
    // Fewer than this and averaging loses the ovality-to-lobing range the model is about.
    if (n_ / block_ < ElasticOptions::kFewestColumns) block_ = 1;
    if (block_ > 1) {
      const std::shared_ptr<const std::vector<double>> kernel =
          SolveColumnKernel(shared_prepare(), n_, block_);
      solve_shaft_ = OnSolveColumns(v_shaft_, shaft_rows_, n_, block_, *kernel);
      solve_bushing_ = OnSolveColumns(v_bushing_, bushing_rows_, n_, block_, *kernel);
    } else {
      solve_shaft_.resize(0, 0);
      solve_bushing_.resize(0, 0);
    }
    const PressFitDimensions d = PressFitDimensionsOf(inner, outer);
    PressFitSection section;
    section.d1 = d.d1;
    section.d2 = d.d2;
    section.di = d.di;
    section.shaft = inner.material;
    section.hub = outer.material;
    section.plane_strain = options.plane_strain;
    hub_modes_.clear();
    shaft_modes_.clear();
    axial_coupling_ = options.axial_coupling;
    coupled_orders_.clear();
    if (options.axial_coupling) {
      // No order past the solve's columns can resolve.
      for (int order = 1; order <= std::min(options.axial_orders, n_ / block_ / 2); ++order) {
        coupled_orders_.push_back(order);
      }
    }
    solver_.emplace(SectionSolver(shared_prepare(), section, n_ / block_, coupled_orders_));
    if (options.axial_coupling) {
      AxialBody hub;
      hub.inner_radius = 0.5 * d.d1;
      hub.outer_radius = 0.5 * d.d2;
      hub.loaded_inside = true;
      hub.material = outer.material;
      hub.held_faces = options.plane_strain;
      AxialBody shaft = hub;
      shaft.inner_radius = 0.5 * d.di;
      shaft.outer_radius = 0.5 * d.d1;
      shaft.loaded_inside = false;
      shaft.material = inner.material;
      // The coupling's rows: each part's grid rows, split into equal parts no longer than the
      // shortest row of either part (the depth step's scale), so that a section that covers part
      // of a row (the shaft's end half a row into the bore) loads that part and not the row's
      // whole length (a 20 mm shaft of 1 mm rows 0.5 mm in: 27 % low against CalculiX on whole
      // rows).
      auto refine = [min_row](const std::vector<double>& edges) {
        std::vector<double> out{edges.front()};
        for (std::size_t i = 1; i < edges.size(); ++i) {
          const double len = edges[i] - edges[i - 1];
          const int parts = std::max(1, static_cast<int>(std::ceil(len / min_row - 1e-9)));
          for (int q = 1; q < parts; ++q) out.push_back(edges[i - 1] + len * q / parts);
          out.push_back(edges[i]);
        }
        return out;
      };
      hub_coupling_rows_ = refine(bushing_edges_);
      shaft_coupling_rows_ = refine(shaft_edges_);
      // One finite-element solve per row (half of them where the rows mirror) and mode, and a
      // coupled solve over every engaged section: past this the prepare takes minutes (the
      // breathing mode alone: 1000 rows 6 min, 400 rows 20 s on a two-core machine; each
      // further order's elements cost about twice its own).
      for (const auto& [part, rows] :
           {std::pair{"bushing", static_cast<int>(hub_coupling_rows_.size()) - 1},
            {"shaft", static_cast<int>(shaft_coupling_rows_.size()) - 1}}) {
        if (rows > AxialCoupling::kMostRows) {
          throw UserError(std::string("the elastic model's axial coupling takes at most ") +
                          std::to_string(AxialCoupling::kMostRows) +
                          " rows per part (grid rows split to the shortest row of either part); "
                          "the " +
                          part + " has " + std::to_string(rows) +
                          ": take fewer model.resolution rows or set "
                          "model.options.axial_coupling: false (plane sections)");
        }
      }
      // The elements are solved when a depth step first needs them (EnsurePartModes): a
      // clearance fit's tables may have none that interferes.
      hub_body_ = hub;
      shaft_body_ = shaft;
    }
    freedom.tilt = options.tilt;
    freedom.tilt_stiffness = options.tilt_stiffness;
    frame = angle_[0] + std::numbers::pi * (block_ - 1) / n_;
    section_ = section;
    freedom_ = freedom;
    frame_ = frame;
  }

  kappa_.clear();
  curve_tilt_.clear();
  curve_depth_.clear();
  const bool compliant = std::isfinite(settings.held_tilt_stiffness);
  if (!settings.held_tilt.isZero()) {
    if (!settings.held_tilt.allFinite() || settings.held_tilt.norm() >= 0.5 * std::numbers::pi) {
      throw UserError("a held tilt must be finite and below a right angle");
    }
    if (compliant && !(settings.held_tilt_stiffness > 0.0)) {
      throw UserError("a compliant hold's tilt stiffness must be positive");
    }
    if (elastic_ && !compliant) {
      throw UserError(
          "law 'elastic' solves the part's own tilt under interference and takes no rigidly held "
          "tilt; remove the device's tilt or use law 'gps'");
    }
    // A compliant holder's part is aligned by the contact wherever it is forced (the curve
    // below); a rigid holder's keeps its tilt, and the tables are its.
    if (!compliant) kappa_ = ColumnSlopes(settings.held_tilt);
  }

  texture_ = settings.texture == TextureMode::kExpected
                 ? ExpectedInterferenceTable(EquivalentTexture(inner.texture, outer.texture))
                 : ExpectedInterferenceTable();

  // Auto step: the shortest row of either part. Between two row boundaries the slices only change
  // length, so every tabulated quantity is piecewise linear or smooth there; a finer step adds
  // nothing the cells can resolve.
  if (settings.depth_step < 0.0) throw UserError("depth_step must not be negative");
  max_depth_ = shaft_length_ + bushing_length_;
  step_ = settings.depth_step > 0.0 ? settings.depth_step
                                    : std::max(min_row, max_depth_ / kAutoDepthSteps);
  // A run whose device stops short (ModelSettings::reach) needs no table past it: the steps kept
  // are the same bits as in the whole table (a chunk's warm starts only run forwards), and the
  // step stays the whole length's. Two steps and a millimetre of margin cover a lead-in's capture
  // depth and the interpolation's next step.
  if (settings.reach < max_depth_) {
    const double reach = std::max(settings.reach, 0.0) + 1e-3;
    max_depth_ = std::min(max_depth_, (std::ceil(reach / step_) + 2.0) * step_);
  }
  const double steps = std::ceil(max_depth_ / step_);
  // Each step stores up to n + 4 polygon vertices.
  if (!(steps < kMaxDepthSteps) || !(steps * (n_ + 4) < kMaxDepthTableVertices)) {
    throw UserError("depth_step " + MessageNumber(step_) + " m gives " + MessageNumber(steps) +
                    " table rows of up to " + MessageNumber(n_ + 4) +
                    " vertices, more than the analyzer holds; use a coarser step");
  }
  const std::size_t count = static_cast<std::size_t>(steps) + 1;

  depth_.assign(count, 0.0);
  length_ = area_ = volume_ = max_delta_ = depth_;
  resultant_.assign(count, Eigen::Vector2d::Zero());
  anchor_ = resultant_;
  tilt_ = resultant_;
  normal_.assign(count, 0.0);
  empty_.assign(count, 0);
  unconstrained_.assign(count, 0);
  vertex_begin_.assign(count, 0);
  vertex_count_.assign(count, 0);
  // Room for every step's polygon (at most n + 4 vertices) reserved, not touched: the steps join
  // their polygons in depth order without the arrays ever moving, so a tick reads the steps
  // prepared while the next ones are appended (PrepareAhead).
  const std::size_t most_vertices = count * static_cast<std::size_t>(n_ + 4);
  vertices_.clear();
  vertices_.reserve(most_vertices);
  centre_angles_.clear();
  centre_angles_.reserve(most_vertices);
  origin_angles_.clear();
  origin_angles_.reserve(most_vertices);
  centre_fan_.assign(count, 0);
  origin_fan_.assign(count, 0);
  max_vertices_ = 0;
  newton_iterations_ = 0;
  next_step_ = 0;
  step_scratch_ = StepScratch{};
  step_polygon_ = StepPolygon{};
  prepared_steps_.store(0, std::memory_order_release);

  // The compliant holder's curve depends on the parts alone, not on the tables.
  if (compliant && !settings.held_tilt.isZero()) {
    // 32 tilts between none and the holder's: the curve's chord error stays below a few per cent
    // of the tilt where the depth changes fastest (as 1 / tilt).
    constexpr int kCurveTilts = 32;
    const double tilt = settings.held_tilt.norm();
    hold_axis_ = settings.held_tilt / tilt;
    hold_stiffness_ = settings.held_tilt_stiffness;
    for (int i = 1; i <= kCurveTilts; ++i) {
      const double level = tilt * i / kCurveTilts;
      curve_tilt_.push_back(level);
      curve_depth_.push_back(TwoPointDepth(ColumnSlopes(level * hold_axis_)));
    }
  }
  // Nothing past the entrance yet (a pose there reads no table).
  PublishPreparedDepth(0.0);
}

void CylinderContactAnalyzer::JoinPolygon(std::size_t k, const StepPolygon& p) {
  // Past the room reserved the arrays would move under a tick reading them.
  if (vertices_.size() + p.vertices.size() > vertices_.capacity()) {
    throw std::logic_error("cylindrical contact: a step's polygon has more than n + 4 vertices");
  }
  vertex_begin_[k] = static_cast<int>(vertices_.size());
  vertex_count_[k] = static_cast<int>(p.vertices.size());
  max_vertices_ = std::max(max_vertices_, vertex_count_[k]);
  vertices_.insert(vertices_.end(), p.vertices.begin(), p.vertices.end());
  centre_angles_.insert(centre_angles_.end(), p.centre_angles.begin(), p.centre_angles.end());
  origin_angles_.insert(origin_angles_.end(), p.origin_angles.begin(), p.origin_angles.end());
}

void CylinderContactAnalyzer::PublishSteps(std::size_t steps) {
  prepared_steps_.store(steps, std::memory_order_release);
  // Steps 0 .. steps - 1 interpolate every depth up to the last one's.
  PublishPreparedDepth(steps >= depth_.size() ? std::numeric_limits<double>::infinity()
                       : steps > 1            ? static_cast<double>(steps - 1) * step_
                                              : 0.0);
}

bool CylinderContactAnalyzer::DoPrepareAhead(int steps) {
  const std::size_t count = depth_.size();
  for (int done = 0; done < steps && next_step_ < count; ++done) {
    // Chunk by chunk from each chunk's cold start, as DoFinishPrepare's threads take them.
    const std::size_t k = next_step_, first = k - k % kChunkSteps;
    StepScratch& scratch = step_scratch_;
    if (k == first) {
      scratch.Restart(static_cast<std::size_t>(n_), static_cast<std::size_t>(bushing_rows_));
      if (solver_ && !scratch.solver) scratch.solver = solver_;  // its own copy: it keeps state
      ChunkMinima(first, std::min(count, first + kChunkSteps), &scratch);
    }
    // Each step's polygon from empty, as a step of the parallel prepare has its own (a step in
    // interference writes no fan angles, and must not join the step before's).
    step_polygon_.vertices.clear();
    step_polygon_.centre_angles.clear();
    step_polygon_.origin_angles.clear();
    PrepareStep(k, k - first, &scratch, &step_polygon_);
    JoinPolygon(k, step_polygon_);
    ++next_step_;
    const bool chunk_done = next_step_ % kChunkSteps == 0 || next_step_ == count;
    if (chunk_done) newton_iterations_ += scratch.newton_iterations;
    PublishSteps(next_step_);
  }
  return next_step_ < count;
}

void CylinderContactAnalyzer::DoFinishPrepare() {
  // The chunk under way on this thread, then the whole chunks left on the prepare's threads.
  if (next_step_ % kChunkSteps != 0) {
    DoPrepareAhead(static_cast<int>(kChunkSteps - next_step_ % kChunkSteps));
  }
  const std::size_t count = depth_.size();
  if (next_step_ >= count) return;
  // Depth steps in chunks of kChunkSteps, each chunk on one thread from its own cold start (the
  // warm starts below run within a chunk only), so the tables are the same whatever the thread
  // count and whichever steps were prepared ahead. Every step writes its own entries; polygons
  // are joined in step order at the end.
  const std::size_t begin = next_step_ / kChunkSteps;
  const std::size_t chunks = (count + kChunkSteps - 1) / kChunkSteps - begin;
  std::vector<StepPolygon> polygons(count - next_step_);
  std::vector<int> chunk_newton(chunks, 0);
  const std::size_t offset = next_step_;
  ParallelFor(static_cast<int>(chunks), [&](int chunk_begin, int chunk_end) {
    StepScratch scratch;
    for (auto c = static_cast<std::size_t>(chunk_begin); c < static_cast<std::size_t>(chunk_end);
         ++c) {
      scratch.Restart(static_cast<std::size_t>(n_), static_cast<std::size_t>(bushing_rows_));
      if (solver_ && !scratch.solver)
        scratch.solver = solver_;  // a copy per thread: it keeps state
      const std::size_t first = (begin + c) * kChunkSteps,
                        end = std::min(count, first + kChunkSteps);
      ChunkMinima(first, end, &scratch);
      for (std::size_t k = first; k < end; ++k) {
        PrepareStep(k, k - first, &scratch, &polygons[k - offset]);
      }
      chunk_newton[c] = scratch.newton_iterations;
    }
  });
  for (std::size_t k = offset; k < count; ++k) JoinPolygon(k, polygons[k - offset]);
  for (int c : chunk_newton) newton_iterations_ += c;
  next_step_ = count;
  PublishSteps(count);
}

std::vector<double> CylinderContactAnalyzer::ColumnSlopes(const Eigen::Vector2d& rotation) const {
  const Eigen::Vector3d vector(rotation.x(), 0.0, rotation.y());
  const Eigen::Vector3d axis =
      Eigen::AngleAxisd(vector.norm(), vector.normalized()) * Eigen::Vector3d::UnitY();
  const Eigen::Vector2d slope(axis.x() / axis.y(), axis.z() / axis.y());
  std::vector<double> kappa(static_cast<std::size_t>(n_));
  for (std::size_t j = 0; j < kappa.size(); ++j) {
    kappa[j] = slope.x() * cos_[j] + slope.y() * sin_[j];
  }
  return kappa;
}

void CylinderContactAnalyzer::TiltedMinima(double depth, const std::vector<Slice>& slices,
                                           const std::vector<double>& kappa, double* h) const {
  double pos = std::max(depth - shaft_length_, 0.0);
  for (const Slice& sl : slices) {
    const double* vs = v_shaft_.data() + static_cast<Eigen::Index>(sl.shaft_row) * n_;
    const double* vb = v_bushing_.data() + static_cast<Eigen::Index>(sl.bushing_row) * n_;
    // Behind the leading end (<= 0): the slice's two ends.
    const double near = pos + sl.length - depth, far = pos - depth;
    for (std::size_t j = 0; j < kappa.size(); ++j) {
      const double widening = -std::max(near * kappa[j], far * kappa[j]);
      h[j] = std::min(h[j], vb[j] - vs[j] + smoothing_ + widening);
    }
    pos += sl.length;
  }
}

bool CylinderContactAnalyzer::TiltedSpaceEmpty(double depth,
                                               const std::vector<double>& kappa) const {
  std::vector<Slice> slices;
  SlicesAt(depth, &slices);
  if (slices.empty()) return false;
  std::vector<double> h(kappa.size(), std::numeric_limits<double>::infinity());
  TiltedMinima(depth, slices, kappa, h.data());
  std::vector<Eigen::Vector2d> polygon;
  return !half_planes_.Intersect(h, &polygon);
}

double CylinderContactAnalyzer::TwoPointDepth(const std::vector<double>& kappa) const {
  // The first tabulated step past which the part no longer fits, then bisection within it.
  double lo = 0.0;
  for (std::size_t k = 1; k < depth_.size(); ++k) {
    const double hi = static_cast<double>(k) * step_;
    if (!TiltedSpaceEmpty(hi, kappa)) {
      lo = hi;
      continue;
    }
    double a = lo, b = hi;
    while (b - a > 1e-6) {
      const double m = 0.5 * (a + b);
      (TiltedSpaceEmpty(m, kappa) ? b : a) = m;
    }
    return b;
  }
  return max_depth_;
}

void CylinderContactAnalyzer::StepScratch::Restart(std::size_t columns, std::size_t bore_rows) {
  col_a.resize(columns);
  col_b.resize(columns);
  proj.resize(columns);
  warm = Eigen::Vector2d::Zero();
  elastic_warm = Eigen::Vector4d::Zero();
  row_contact.assign(bore_rows, {});
  row_contact_step.assign(bore_rows, std::numeric_limits<std::size_t>::max());
  row_factors.assign(bore_rows, {});
  coupling = CouplingScratch{};
  newton_iterations = 0;
}

// Energy sum(w * max(0, p.u_j - st)^2) with its per-column first and second moments, one scan.
double CylinderContactAnalyzer::Energy(const Eigen::Vector2d& p, StepScratch* s) const {
  const std::size_t n = static_cast<std::size_t>(n_);
  std::fill(s->col_a.begin(), s->col_a.end(), 0.0);
  std::fill(s->col_b.begin(), s->col_b.end(), 0.0);
  s->col_energy.assign(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) s->proj[j] = p.x() * cos_[j] + p.y() * sin_[j];
  const std::size_t rows = s->st.size() / n;
  for (std::size_t r = 0; r < rows; ++r) {
    const double* g = s->st.data() + r * n;
    const double* a = s->w.data() + r * n;
    EnergyMoments(s->col_energy.data(), s->col_a.data(), s->col_b.data(), s->proj.data(), g, a, n);
  }
  double e = 0.0;
  for (std::size_t j = 0; j < n; ++j) e += s->col_energy[j];
  return e;
}

void CylinderContactAnalyzer::TiltedChunkMinima(std::size_t first, std::size_t end,
                                                StepScratch* s) const {
  const std::size_t n = static_cast<std::size_t>(n_);
  const std::size_t steps = end - first;
  s->chunk_slices.resize(std::max(s->chunk_slices.size(), steps));
  s->chunk_h.assign(steps * n, std::numeric_limits<double>::infinity());
  for (std::size_t t = 0; t < steps; ++t) {
    const double depth = static_cast<double>(first + t) * step_;
    SlicesAt(depth, &s->chunk_slices[t]);
    TiltedMinima(depth, s->chunk_slices[t], kappa_, s->chunk_h.data() + t * n);
  }
}

void CylinderContactAnalyzer::ChunkMinima(std::size_t first, std::size_t end,
                                          StepScratch* s) const {
  if (!kappa_.empty()) {
    TiltedChunkMinima(first, end, s);
    return;
  }
  const std::size_t n = static_cast<std::size_t>(n_);
  const std::size_t steps = end - first;
  s->chunk_slices.resize(std::max(s->chunk_slices.size(), steps));
  s->chunk_h.assign(steps * n, std::numeric_limits<double>::infinity());
  s->pairs.clear();
  for (std::size_t t = 0; t < steps; ++t) {
    SlicesAt(static_cast<double>(first + t) * step_, &s->chunk_slices[t]);
    for (const Slice& sl : s->chunk_slices[t]) {
      s->pairs.push_back(
          {static_cast<int>(t / kMinimaBlock), sl.shaft_row, static_cast<int>(t), sl.bushing_row});
    }
  }
  // Shaft row by shaft row within blocks of kMinimaBlock steps: each row is read from memory
  // once per block, and the bore rows it meets (consecutive from step to step) and the block's
  // minima stay in cache. At 10^6 cells the two shapes are 12 MB and a step reads 8 MB of them,
  // so a step at a time is bound by memory bandwidth. The minimum is exact: the order changes
  // nothing. Sorted by (block, shaft row) in one counting pass: the pairs were made step by step
  // and slice by slice (bore rows ascending), so each bucket is already in (step, bore row) order.
  const auto rows = static_cast<std::size_t>(shaft_rows_);
  auto bucket = [rows](const RowPair& p) {
    return static_cast<std::size_t>(p.block) * rows + static_cast<std::size_t>(p.shaft_row);
  };
  s->bucket.assign((steps + kMinimaBlock - 1) / kMinimaBlock * rows + 1, 0);
  for (const RowPair& p : s->pairs) ++s->bucket[bucket(p) + 1];
  for (std::size_t b = 1; b < s->bucket.size(); ++b) s->bucket[b] += s->bucket[b - 1];
  s->sorted_pairs.resize(s->pairs.size());
  for (const RowPair& p : s->pairs) s->sorted_pairs[s->bucket[bucket(p)]++] = p;
  assert(std::is_sorted(s->sorted_pairs.begin(), s->sorted_pairs.end()));
  const auto& pairs = s->sorted_pairs;
  for (std::size_t q = 0; q < pairs.size();) {
    const RowPair& p = pairs[q];
    const double* vs = v_shaft_.data() + static_cast<Eigen::Index>(p.shaft_row) * n_;
    const double* vb = v_bushing_.data() + static_cast<Eigen::Index>(p.bushing_row) * n_;
    double* h = s->chunk_h.data() + static_cast<std::size_t>(p.step) * n;
    if (q + 1 < pairs.size() && pairs[q + 1].shaft_row == p.shaft_row &&
        pairs[q + 1].step == p.step) {
      const double* vb1 =
          v_bushing_.data() + static_cast<Eigen::Index>(pairs[q + 1].bushing_row) * n_;
      MinOfDifference2(h, vb, vb1, vs, smoothing_, n);
      q += 2;
    } else {
      MinOfDifference(h, vb, vs, smoothing_, n);
      ++q;
    }
  }
}

void CylinderContactAnalyzer::PrepareStep(std::size_t k, std::size_t t, StepScratch* s,
                                          StepPolygon* out) {
  const std::size_t n = static_cast<std::size_t>(n_);
  const double depth = static_cast<double>(k) * step_;
  depth_[k] = depth;
  const std::vector<Slice>& slices = s->chunk_slices[t];
  if (slices.empty()) {
    unconstrained_[k] = 1;
    return;
  }
  // First only what the assembly space needs: the smallest gap per column over the slices (eq. 8,
  // ChunkMinima) and the engaged length and area. The per-cell gaps and weights are filled below
  // only for the steps that use them (interference, or a texture that is not sharp).
  const std::span<const double> h(s->chunk_h.data() + t * n, n);
  double length = 0.0, area = 0.0;
  for (const Slice& sl : slices) {
    const auto i = static_cast<std::size_t>(sl.shaft_row);
    length += sl.length;
    area += shaft_row_area_[i] * sl.length / (shaft_edges_[i + 1] - shaft_edges_[i]);
  }
  length_[k] = length;
  area_[k] = area;
  auto fill_cells = [&] {
    s->st.resize(slices.size() * n);
    s->w.resize(slices.size() * n);
    double pos = std::max(depth - shaft_length_, 0.0);  // the slice's start along the bore
    for (std::size_t sl = 0; sl < slices.size(); ++sl) {
      // A held tilt widens a slice's gaps by its middle's distance behind the leading end.
      const double behind = depth - (pos + 0.5 * slices[sl].length);
      pos += slices[sl].length;
      const auto i = static_cast<std::size_t>(slices[sl].shaft_row);
      const double share = slices[sl].length / (shaft_edges_[i + 1] - shaft_edges_[i]);
      const double* vs = v_shaft_.data() + static_cast<Eigen::Index>(slices[sl].shaft_row) * n_;
      const double* vb = v_bushing_.data() + static_cast<Eigen::Index>(slices[sl].bushing_row) * n_;
      const double* a = shaft_area_.data() + static_cast<Eigen::Index>(slices[sl].shaft_row) * n_;
      for (std::size_t j = 0; j < n; ++j) {
        s->st[sl * n + j] =
            vb[j] - vs[j] + smoothing_ + (kappa_.empty() ? 0.0 : behind * kappa_[j]);
        s->w[sl * n + j] = a[j] * share;
      }
    }
  };

  Eigen::Vector2d anchor;
  std::vector<Eigen::Vector2d>& polygon = out->vertices;
  if (half_planes_.Intersect(h, &polygon)) {
    const int size = static_cast<int>(polygon.size());
    anchor = PolygonCentroid(polygon.data(), size);
    out->centre_angles.assign(polygon.size(), 0.0);
    out->origin_angles.assign(polygon.size(), 0.0);
    centre_fan_[k] = FanAngles(polygon.data(), size, anchor, out->centre_angles.data());
    origin_fan_[k] =
        FanAngles(polygon.data(), size, Eigen::Vector2d::Zero(), out->origin_angles.data());
    s->warm = anchor;
    if (!texture_.sharp()) fill_cells();
  } else if (elastic_) {
    polygon.clear();
    fill_cells();
    empty_[k] = 1;
    const std::size_t ne = n / static_cast<std::size_t>(block_);
    s->elastic_gap.assign(slices.size() * ne, 0.0);
    s->sections.assign(slices.size(), ContactSection{});
    s->section_start.resize(slices.size());
    s->section_length.resize(slices.size());
    const double lo = std::max(depth - shaft_length_, 0.0);
    double pos = lo, middle = lo + 0.5 * length;
    for (std::size_t sl = 0; sl < slices.size(); ++sl) {
      ContactSection& sec = s->sections[sl];
      sec.gap = s->elastic_gap.data() + sl * ne;
      sec.y = pos + 0.5 * slices[sl].length - middle;
      s->section_start[sl] = pos;
      pos += slices[sl].length;
      SolveGaps(slices[sl], s->elastic_gap.data() + sl * ne);
      sec.cell_area = s->w[sl * n] * block_;  // equal cells along a slice
      const auto row = static_cast<std::size_t>(slices[sl].bushing_row);
      // Only from the step just before (the row's set of older steps is no guide).
      const bool last_step = k > 0 && s->row_contact_step[row] == k - 1;
      sec.warm_contact = last_step ? s->row_contact[row].data() : nullptr;
      sec.factorization = &s->row_factors[row];
      s->section_length[sl] = slices[sl].length;
    }
    if (axial_coupling_) EnsurePartModes();
    const RigidContactResult r =
        SolveSections(&*s->solver, s->sections, s->section_start, s->section_length,
                      depth - shaft_length_, s->elastic_gap.data(), s->elastic_warm, &s->coupling,
                      PartModes{&hub_modes_, &shaft_modes_});
    for (std::size_t sl = 0; sl < slices.size(); ++sl) {
      const auto row = static_cast<std::size_t>(slices[sl].bushing_row);
      s->row_contact[row] = s->solver->contact_sets()[sl];
      s->row_contact_step[row] = k;
    }
    s->elastic_warm << r.offset, r.tilt;
    anchor = Rotate(r.offset, frame_);
    tilt_[k] = Rotate(r.tilt, frame_);
    normal_[k] = r.normal_force;
    s->warm = anchor;
  } else {
    polygon.clear();
    fill_cells();
    empty_[k] = 1;
    // Newton on the convex piecewise-quadratic energy, Armijo backtracking.
    Eigen::Vector2d p = s->warm;
    // Trial points are evaluated with their moments, so that an accepted one is the next
    // iteration's point without a second scan of the cells (each scan is most of a step's cost).
    double e0 = Energy(p, s);
    for (int it = 0; it < 100; ++it) {
      ++s->newton_iterations;
      Eigen::Vector2d grad(0.0, 0.0);
      Eigen::Matrix2d hess = Eigen::Matrix2d::Zero();
      for (std::size_t j = 0; j < n; ++j) {
        const Eigen::Vector2d u(cos_[j], sin_[j]);
        grad += 2.0 * s->col_a[j] * u;
        hess += 2.0 * s->col_b[j] * u * u.transpose();
      }
      const double trace = hess.trace();
      if (!(trace > 0.0)) break;  // no cell interferes: p is already a minimiser
      hess += 1e-12 * trace * Eigen::Matrix2d::Identity();
      const Eigen::Vector2d dir = -hess.ldlt().solve(grad);
      double alpha = 1.0;
      const double slope = grad.dot(dir);
      double trial = Energy(p + alpha * dir, s);
      while (alpha > 1e-12 && trial > e0 + 1e-4 * alpha * slope) {
        alpha *= 0.5;
        trial = Energy(p + alpha * dir, s);
      }
      p += alpha * dir;
      e0 = trial;
      // A picometre-scale step on micrometre interferences: converged.
      if ((alpha * dir).norm() < 1e-13) break;
    }
    anchor = p;
    s->warm = p;
  }
  anchor_[k] = anchor;

  // Interference at the anchor: none is possible with a sharp contact inside the polygon.
  if (empty_[k] || !texture_.sharp()) {
    double volume = 0.0, max_delta = 0.0;
    Eigen::Vector2d resultant(0.0, 0.0);
    for (std::size_t j = 0; j < n; ++j) s->proj[j] = anchor.x() * cos_[j] + anchor.y() * sin_[j];
    std::fill(s->col_a.begin(), s->col_a.end(), 0.0);
    for (std::size_t row = 0; row < s->st.size() / n; ++row) {
      const double* g = s->st.data() + row * n;
      const double* w = s->w.data() + row * n;
      for (std::size_t j = 0; j < n; ++j) {
        const double d = texture_(g[j] - s->proj[j]);
        s->col_a[j] += w[j] * d;
        max_delta = std::max(max_delta, d);
      }
    }
    for (std::size_t j = 0; j < n; ++j) {
      volume += s->col_a[j];
      resultant += s->col_a[j] * Eigen::Vector2d(cos_[j], sin_[j]);
    }
    volume_[k] = volume;
    max_delta_[k] = max_delta;
    resultant_[k] = resultant;
  }
}

void CylinderContactAnalyzer::SolveGaps(const Slice& slice, double* out) const {
  if (block_ == 1) {
    const double* vb = v_bushing_.data() + static_cast<std::ptrdiff_t>(slice.bushing_row) * n_;
    const double* vs = v_shaft_.data() + static_cast<std::ptrdiff_t>(slice.shaft_row) * n_;
    for (int j = 0; j < n_; ++j) out[j] = vb[j] - vs[j] + smoothing_;
    return;
  }
  const auto ne = static_cast<Eigen::Index>(n_ / block_);
  Eigen::Map<Eigen::VectorXd>(out, ne) = solve_bushing_.col(slice.bushing_row) -
                                         solve_shaft_.col(slice.shaft_row) +
                                         Eigen::VectorXd::Constant(ne, smoothing_);
}

void CylinderContactAnalyzer::SlicesAt(double depth, std::vector<Slice>* slices) const {
  slices->clear();
  const double shift = depth - shaft_length_;  // bushing coordinate of the shaft's trailing end
  const double lo = std::max(shift, 0.0);
  const double hi = std::min(depth, bushing_length_);
  if (!(hi > lo)) return;
  // First rows containing lo.
  int i = static_cast<int>(std::upper_bound(shaft_edges_.begin(), shaft_edges_.end(), lo - shift) -
                           shaft_edges_.begin()) -
          1;
  int k = static_cast<int>(std::upper_bound(bushing_edges_.begin(), bushing_edges_.end(), lo) -
                           bushing_edges_.begin()) -
          1;
  i = std::clamp(i, 0, shaft_rows_ - 1);
  k = std::clamp(k, 0, bushing_rows_ - 1);
  // Slivers below a femtometre are rounding of equal boundaries, not geometry.
  constexpr double kSliver = 1e-15;
  double pos = lo;
  while (pos < hi - kSliver && i < shaft_rows_ && k < bushing_rows_) {
    const double shaft_end = shaft_edges_[static_cast<std::size_t>(i) + 1] + shift;
    const double bushing_end = bushing_edges_[static_cast<std::size_t>(k) + 1];
    const double next = std::min({shaft_end, bushing_end, hi});
    if (next - pos > kSliver) slices->push_back({i, k, next - pos});
    if (shaft_end <= next + kSliver) ++i;
    if (bushing_end <= next + kSliver) ++k;
    pos = next;
  }
}

bool CylinderContactAnalyzer::Locate(double depth, std::size_t* k, double* t) const noexcept {
  if (!(depth > 0.0) || !(depth < max_depth_)) return false;
  // Progressive prepare: the steps written so far (ContactAnalyzer::Evaluate keeps the depth
  // within them; rounding at the last one's depth takes it as the end of the interval before).
  const std::size_t prepared = prepared_steps_.load(std::memory_order_acquire);
  if (prepared < 2) return false;
  const double s = depth / step_;
  const std::size_t last = prepared - 1;
  std::size_t i = static_cast<std::size_t>(s);
  if (i >= last) i = last - 1;
  *k = i;
  *t = std::clamp(s - static_cast<double>(i), 0.0, 1.0);
  return true;
}

Eigen::Vector2d CylinderContactAnalyzer::AnchorAt(std::size_t k,
                                                  const Eigen::Vector2d& x) const noexcept {
  if (unconstrained_[k]) return x;
  if (empty_[k]) return anchor_[k];
  PolygonFan fan;
  if (centre_fan_[k]) fan = {anchor_[k], centre_angles_.data() + vertex_begin_[k]};
  return ProjectOntoPolygon(vertices_.data() + vertex_begin_[k], vertex_count_[k], fan, x);
}

void CylinderContactAnalyzer::DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept {
  *out = ContactState{};
  const Eigen::Vector2d x = pose.offset;
  out->offset_distance = x.norm();
  out->offset_angle = std::atan2(x.y(), x.x());
  std::size_t k = 0;
  double t = 0.0;
  // A non-finite offset is an upstream fault: report no contact rather than NaN forces.
  if (!x.allFinite() || !Locate(pose.depth, &k, &t)) return;
  const double s = 1.0 - t;
  out->engaged_length = s * length_[k] + t * length_[k + 1];
  out->engaged_area = s * area_[k] + t * area_[k + 1];
  out->engaged = out->engaged_length > 0.0;
  if (!out->engaged) return;

  const Eigen::Vector2d anchor = s * AnchorAt(k, x) + t * AnchorAt(k + 1, x);
  const Eigen::Vector2d pen = x - anchor;
  out->penetration = pen.norm();
  if (out->penetration > 0.0) out->penetration_direction = pen / out->penetration;

  const std::size_t nearest = t < 0.5 ? k : k + 1;
  out->interference = empty_[nearest] != 0;
  if (!out->interference && !unconstrained_[nearest]) {
    // The offset's direction (+x at the axis, as its angle's cosine and sine were).
    const Eigen::Vector2d dir = out->offset_distance > 0.0
                                    ? Eigen::Vector2d(x / out->offset_distance)
                                    : Eigen::Vector2d(1, 0);
    PolygonFan fan;
    if (origin_fan_[nearest]) {
      fan = {Eigen::Vector2d::Zero(), origin_angles_.data() + vertex_begin_[nearest]};
    }
    out->assembly_extent =
        RayExtent(vertices_.data() + vertex_begin_[nearest], vertex_count_[nearest], fan, dir);
  }
  out->interference_volume = s * volume_[k] + t * volume_[k + 1];
  out->max_interference = s * max_delta_[k] + t * max_delta_[k + 1];
  out->pressure_resultant = s * resultant_[k] + t * resultant_[k + 1];
  out->normal_force = s * normal_[k] + t * normal_[k + 1];
  out->tilt = s * tilt_[k] + t * tilt_[k + 1];
  if (!curve_depth_.empty() && pose.depth > curve_depth_.back()) {
    // Past two-point contact at the holder's tilt: the part turns to the largest tilt that still
    // fits at this depth, the holder's spring resisting it; the two contacts, at the entrance's
    // edge and at the leading edge (or the bore's far end), carry its moment as a couple.
    double fits = 0.0;
    if (pose.depth >= curve_depth_.front()) {
      fits = curve_tilt_.front() * curve_depth_.front() / pose.depth;  // two-point depth ~ 1/tilt
    } else {
      std::size_t i = curve_depth_.size() - 1;
      while (i > 0 && curve_depth_[i - 1] <= pose.depth) --i;
      const double a = curve_depth_[i - 1], b = curve_depth_[i];  // a > depth >= b
      fits = curve_tilt_[i] + (curve_tilt_[i - 1] - curve_tilt_[i]) * (pose.depth - b) / (a - b);
    }
    const double moment = hold_stiffness_ * (curve_tilt_.back() - fits);
    const double arm = std::min(pose.depth, bushing_length_);
    out->couple_normal = 2.0 * moment / arm;
    out->couple_moment = -moment * hold_axis_;
  }
}

void CylinderContactAnalyzer::DoInterferenceMap(const MatingPose& pose,
                                                Eigen::VectorXd* delta) const {
  delta->setZero(static_cast<Eigen::Index>(shaft_rows_) * n_);
  std::size_t k = 0;
  double t = 0.0;
  if (!pose.offset.allFinite()) throw UserError("interference map of a non-finite axis offset");
  if (!Locate(pose.depth, &k, &t)) return;
  // Where the laws take the axis to be: under interference the energy-minimising position (the
  // offset from it is the radial spring's), in clearance the pose's own offset, so that a shaft
  // pressed against the bore by a radial load shows its contact line.
  const bool interference = empty_[t < 0.5 ? k : k + 1] != 0;
  const Eigen::Vector2d anchor =
      interference
          ? Eigen::Vector2d((1.0 - t) * AnchorAt(k, pose.offset) + t * AnchorAt(k + 1, pose.offset))
          : pose.offset;
  const double shift = pose.depth - shaft_length_;
  for (int i = 0; i < shaft_rows_; ++i) {
    const double pos = shaft_row_centre_[i] + shift;  // bushing coordinate of the row's centre
    if (pos < 0.0 || pos >= bushing_length_) continue;
    int b = static_cast<int>(std::upper_bound(bushing_edges_.begin(), bushing_edges_.end(), pos) -
                             bushing_edges_.begin()) -
            1;
    b = std::clamp(b, 0, bushing_rows_ - 1);
    for (int j = 0; j < n_; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      const double widening = kappa_.empty() ? 0.0 : (pose.depth - pos) * kappa_[jj];
      const double gap = v_bushing_[b * n_ + j] - v_shaft_[i * n_ + j] + smoothing_ + widening -
                         (anchor.x() * cos_[jj] + anchor.y() * sin_[jj]);
      (*delta)[i * n_ + j] = texture_(gap);
    }
  }
}

void CylinderContactAnalyzer::SolvePartModes(std::vector<AxialCoupling>* hub,
                                             std::vector<AxialCoupling>* shaft) const {
  const std::size_t modes = coupled_orders_.size() + 1;  // the breathing mode, then the orders
  hub->assign(modes, AxialCoupling());
  shaft->assign(modes, AxialCoupling());
  // Each part's modes are independent solves of a few milliseconds, which would otherwise hold
  // every other thread of the prepare waiting (EnsurePartModes): the threads take them in turn,
  // each into its own slot.
  ParallelForEach(static_cast<int>(2 * modes), [&](int job) {
    const auto mode = static_cast<std::size_t>(job / 2);
    const int order = mode == 0 ? 0 : coupled_orders_[mode - 1];
    if (job % 2 == 0) {
      (*shaft)[mode] = AxialCoupling(shaft_body_, shaft_coupling_rows_, order);
    } else {
      (*hub)[mode] = AxialCoupling(hub_body_, hub_coupling_rows_, order);
    }
  });
}

void CylinderContactAnalyzer::EnsurePartModes() {
  const std::lock_guard<std::mutex> lock(modes_mutex_);
  if (!hub_modes_.empty()) return;
  SharedPrepare* shared = shared_prepare();
  if (shared == nullptr) {
    SolvePartModes(&hub_modes_, &shaft_modes_);
    return;
  }
  // The elements depend on the parts' bodies and coupling rows alone, never on their drawn
  // variations: one solve serves every pair of a study (a tenth of a transition fit's prepare).
  std::string key = "cylindrical part modes:";
  for (const AxialBody* body : {&hub_body_, &shaft_body_}) {
    for (double x : {body->inner_radius, body->outer_radius, body->material.youngs_modulus,
                     body->material.poisson}) {
      AppendKey(&key, x);
    }
    key += body->loaded_inside ? "i" : "o";
    key += body->held_faces ? "h;" : "f;";
  }
  for (const std::vector<double>* rows : {&hub_coupling_rows_, &shaft_coupling_rows_}) {
    for (double x : *rows) AppendKey(&key, x);
    key += ';';
  }
  for (int order : coupled_orders_) key += std::to_string(order) + ',';
  struct Modes {
    std::vector<AxialCoupling> hub, shaft;
  };
  const std::shared_ptr<const Modes> modes = shared->Get<Modes>(key, [this] {
    Modes m;
    SolvePartModes(&m.hub, &m.shaft);
    return m;
  });
  hub_modes_ = modes->hub;
  shaft_modes_ = modes->shaft;
}

RigidContactResult CylinderContactAnalyzer::SolveSections(
    RigidSectionContact* solver, std::span<ContactSection> sections, std::span<const double> start,
    std::span<const double> length, double shift, double* gaps, const Eigen::Vector4d& warm,
    CouplingScratch* scratch, const PartModes& part_modes) const {
  if (!axial_coupling_ || sections.empty()) return solver->Solve(sections, freedom_, warm);
  const std::size_t modes = coupled_orders_.size() + 1;  // the breathing mode, then the orders
  assert(part_modes[0]->size() == modes && part_modes[1]->size() == modes);
  const auto ne = static_cast<std::size_t>(solver->columns());
  const std::size_t count = sections.size();
  const auto m = static_cast<Eigen::Index>(count);
  // Components: the breathing mode, then cos and sin of each coupled order.
  const Eigen::MatrixXd& basis = solver->shift_basis();
  const auto nc = static_cast<std::size_t>(basis.cols());
  assert(nc == 2 * modes - 1);
  auto mode_of = [](std::size_t component) { return (component + 1) / 2; };
  CouplingScratch& c = *scratch;
  // A section's amplitudes from its column pressures: the mean, and twice the mean of p cos and
  // p sin (the pressures' Fourier coefficients, on the basis the gap shifts use).
  c.weights = basis / static_cast<double>(ne);
  c.weights.rightCols(static_cast<Eigen::Index>(nc) - 1) *= 2.0;
  // The same weights per component, for the amplitudes' response in the Newton system.
  Eigen::VectorXd w =
      Eigen::VectorXd::Constant(static_cast<Eigen::Index>(nc), 2.0 / static_cast<double>(ne));
  w[0] = 1.0 / static_cast<double>(ne);
  // The parts' coupling rows and modes, the hub's then the shaft's; a section's start in the
  // part's coordinates is its bore coordinate less the part's offset.
  const std::array<const std::vector<double>*, 2> rows{&hub_coupling_rows_, &shaft_coupling_rows_};
  const std::array<double, 2> offset{0.0, shift};
  auto row_length = [](const std::vector<double>& edges, int i) {
    return edges[static_cast<std::size_t>(i) + 1] - edges[static_cast<std::size_t>(i)];
  };
  for (int q = 0; q < 2; ++q) {
    CouplingScratch::Part& part = c.part[static_cast<std::size_t>(q)];
    const std::vector<double>& edges = *rows[static_cast<std::size_t>(q)];
    // Rows keep the last solve's pressures (the last depth step's: the engaged pattern has moved
    // by a step, most rows' pressures barely change); none at the start of a chunk.
    part.pressure.resize(nc * (edges.size() - 1), 0.0);
    part.extra.resize(part.pressure.size());
    // Each section's overlap with the part's coupling rows: rows, and the overlap's length.
    part.cover.clear();
    part.first.resize(count + 1);
    for (std::size_t s = 0; s < count; ++s) {
      part.first[s] = part.cover.size();
      const double lo = start[s] - offset[static_cast<std::size_t>(q)];
      const double hi = start[s] + length[s] - offset[static_cast<std::size_t>(q)];
      auto i =
          static_cast<int>(std::upper_bound(edges.begin(), edges.end(), lo) - edges.begin()) - 1;
      i = std::clamp(i, 0, static_cast<int>(edges.size()) - 2);
      for (; i + 1 < static_cast<int>(edges.size()) && edges[static_cast<std::size_t>(i)] < hi;
           ++i) {
        const double overlap = std::min(hi, edges[static_cast<std::size_t>(i) + 1]) -
                               std::max(lo, edges[static_cast<std::size_t>(i)]);
        if (overlap > 0.0) part.cover.emplace_back(i, overlap);
      }
    }
    part.first[count] = part.cover.size();
  }
  // The rows' pressure amplitudes from a section's (each row's share: the overlap over its
  // length); `amplitude` holds the section's nc components.
  auto add_pressure = [&](std::size_t s, const double* amplitude) {
    for (int q = 0; q < 2; ++q) {
      CouplingScratch::Part& part = c.part[static_cast<std::size_t>(q)];
      const std::size_t part_rows = rows[static_cast<std::size_t>(q)]->size() - 1;
      for (std::size_t k = part.first[s]; k < part.first[s + 1]; ++k) {
        const auto [row, overlap] = part.cover[k];
        const double share = overlap / row_length(*rows[static_cast<std::size_t>(q)], row);
        for (std::size_t comp = 0; comp < nc; ++comp) {
          part.pressure[comp * part_rows + static_cast<std::size_t>(row)] +=
              amplitude[comp] * share;
        }
      }
    }
  };
  // The extra displacement the rows' pressures give each section and component (component-major):
  // the overlap-weighted mean of its rows' in either part. Only the rows the sections cover are
  // read, so only theirs are computed (the shaft's rows out of the bore are most of its rows).
  auto extra_at_sections = [&](double* out) {
    for (int q = 0; q < 2; ++q) {
      CouplingScratch::Part& part = c.part[static_cast<std::size_t>(q)];
      const std::size_t part_rows = rows[static_cast<std::size_t>(q)]->size() - 1;
      int lo = static_cast<int>(part_rows), hi = 0;
      for (const auto& [row, overlap] : part.cover) {
        lo = std::min(lo, row);
        hi = std::max(hi, row + 1);
      }
      if (hi <= lo) continue;
      for (std::size_t comp = 0; comp < nc; ++comp) {
        (*part_modes[static_cast<std::size_t>(q)])[mode_of(comp)].ExtraDisplacement(
            part.pressure.data() + comp * part_rows, part.extra.data() + comp * part_rows, lo,
            hi - lo);
      }
    }
    for (std::size_t comp = 0; comp < nc; ++comp) {
      for (std::size_t s = 0; s < count; ++s) {
        double x = 0.0;
        for (int q = 0; q < 2; ++q) {
          const CouplingScratch::Part& part = c.part[static_cast<std::size_t>(q)];
          const double* extra =
              part.extra.data() + comp * (rows[static_cast<std::size_t>(q)]->size() - 1);
          for (std::size_t k = part.first[s]; k < part.first[s + 1]; ++k) {
            x += extra[static_cast<std::size_t>(part.cover[k].first)] * part.cover[k].second;
          }
        }
        out[comp * count + s] = x / length[s];
      }
    }
  };
  // Moves every section's gaps by the components `by` (component-major), left section-major in
  // c.section_shift for the solver.
  auto shift_gaps = [&](const std::vector<double>& by) {
    c.section_shift.resize(count * nc);
    for (std::size_t s = 0; s < count; ++s) {
      Eigen::Map<Eigen::VectorXd> gap(gaps + s * ne, static_cast<Eigen::Index>(ne));
      for (std::size_t comp = 0; comp < nc; ++comp) {
        const double x = by[comp * count + s];
        c.section_shift[s * nc + comp] = x;
        if (x == 0.0) continue;
        if (comp == 0) {
          gap.array() += x;
        } else {
          gap += x * basis.col(static_cast<Eigen::Index>(comp));
        }
      }
    }
  };
  c.shift.assign(nc * count, 0.0);
  extra_at_sections(c.shift.data());
  shift_gaps(c.shift);
  // The rigid equilibrium and the coupling are iterated together, one contact evaluation per
  // step of both: each evaluation's Newton point is where the next evaluates, with the gaps the
  // coupling's step moved (solving the rigid equilibrium to rounding for every coupling step took
  // two evaluations a step, the second only to confirm a Newton step at unchanged gaps).
  // Near the equilibrium (a thousandth of the load unbalanced) the contact set no longer changes
  // in a Newton step and the joint step is as good as the separate ones; further out the rigid
  // steps are taken on their own (evaluated, with line search), or the coupling, fed pressures
  // of a part still moving between contact sets, oscillates (measured: three times the coupling
  // steps on a light transition fit).
  constexpr double kHandoff = 1e-3;
  // The coupling iteration's tolerance: its shifts' change relative to their size.
  constexpr double kShiftTolerance = 1e-3;
  RigidContactResult r = solver->Solve(sections, freedom_, warm, {}, kHandoff);
  c.target.resize(nc * count);
  c.section_contact.resize(count);
  // Each section's next solve starts from the contact set its last one found.
  auto warm_from_last_solve = [&] {
    for (std::size_t s = 0; s < count; ++s) {
      c.section_contact[s] = solver->contact_sets()[s];
      sections[s].warm_contact = c.section_contact[s].data();
    }
  };
  c.step.assign(nc * count, 0.0);
  c.back.resize(nc * count);
  // Each Newton step converges in a few solves; this bounds a pathological step's cost.
  constexpr int kMaxCouplingSolves = 20;
  // Where the contact sets change under a step (a column at the edge of contact), the Newton
  // system's J is wrong on one side and its steps stop reducing the residual: the line search cuts
  // them to a 16th or less, and the iteration creeps (measured on the pin: left to run, 14 of its
  // 47 depth steps spend all 20 solves within 1 to 3.6 tolerances of the answer, and end wherever
  // the last step leaves them, up to 5 tolerances off). There the iteration stops at the best point
  // it found if that is within kStalledTolerances (a hundredth of the shift: ten nanometres on a
  // micrometre); the bound on solves also ends at the best point. The pin's axial force stays
  // within 5e-6 of itself, in 649 solves instead of 772; no other shipped scene stalls.
  constexpr double kStalledTolerances = 10.0;
  // Closer in, a full Newton step that makes the residual worse has crossed such a kink already:
  // the halvings then gain a tenth a cycle (full, half, quarter, eighth step, and full again:
  // measured on the pin, cycles to the bound on solves from 3 tolerances off). Within
  // kKinkTolerances the best point is taken at once: the pin's coupling iterations 205, not 300,
  // its axial force within 4e-4 of itself, an H7/n6's unchanged (its kinks meet it further out);
  // at the stall's 10 the H7/n6's force would move by 7e-3, so this bound is the tighter.
  constexpr double kKinkTolerances = 4.0;
  double last_residual = std::numeric_limits<double>::infinity(), applied = 1.0;
  double best_residual = std::numeric_limits<double>::infinity(), best_ratio = 0.0;
  std::vector<double>& best_shift = c.best;
  std::vector<double> amplitude(nc);
  bool coupling_built = false;  // the Newton system's M, built at the first step that needs it
  for (int solve = 0;; ++solve) {
    for (CouplingScratch::Part& part : c.part) {
      std::fill(part.pressure.begin(), part.pressure.end(), 0.0);
    }
    int all_round = 1;  // every section in contact all round
    for (std::size_t s = 0; s < count; ++s) {
      const double* p = solver->pressures().data() + s * ne;
      const std::vector<char>& set = solver->contact_sets()[s];
      double sum = 0.0;
      for (std::size_t j = 0; j < ne; ++j) sum += p[j];
      for (std::size_t j = 0; j < ne; ++j) all_round &= set[j] != 0 ? 1 : 0;
      amplitude[0] = sum / static_cast<double>(ne);
      const Eigen::Map<const Eigen::VectorXd> ps(p, static_cast<Eigen::Index>(ne));
      for (std::size_t comp = 1; comp < nc; ++comp) {
        amplitude[comp] = c.weights.col(static_cast<Eigen::Index>(comp)).dot(ps);
      }
      add_pressure(s, amplitude.data());
    }
    extra_at_sections(c.target.data());
    double change = 0.0, size = 0.0;
    for (std::size_t at = 0; at < nc * count; ++at) {
      change = std::max(change, std::abs(c.target[at] - c.shift[at]));
      size = std::max(size, std::abs(c.target[at]));
    }
    // A thousandth of the shift: a nanometre on micrometre shifts, below what the tables resolve.
    const double tolerance = kShiftTolerance * size + 1e-13;
    double residual = 0.0;
    for (std::size_t at = 0; at < nc * count; ++at) {
      residual += (c.target[at] - c.shift[at]) * (c.target[at] - c.shift[at]);
    }
    if (residual < best_residual) {
      best_residual = residual;
      best_ratio = change / tolerance;
      best_shift = c.shift;
    }
    const bool worse = solve > 0 && residual > (1.0 - 1e-4 * applied) * last_residual;
    const bool stalled = solve > 0 && ((applied <= 1.0 / 16 && best_ratio <= kStalledTolerances) ||
                                       (worse && best_ratio <= kKinkTolerances));
    if ((stalled || solve == kMaxCouplingSolves) && residual > best_residual) {
      // Back to the best point: its gaps, and its pressures solved again.
      for (std::size_t at = 0; at < nc * count; ++at) c.back[at] = best_shift[at] - c.shift[at];
      shift_gaps(c.back);
      c.shift = best_shift;
      warm_from_last_solve();
      r = solver->Solve(sections, freedom_, r.next, c.section_shift);
      break;
    }
    if (change <= tolerance || stalled || solve == kMaxCouplingSolves) {
      // The rigid equilibrium to rounding at these gaps (its last step usually confirms it).
      if (!r.converged) {
        c.section_dp.assign(count * nc, 0.0);  // no gap moved since the last evaluation
        r = solver->Solve(sections, freedom_, r.next, c.section_dp);
      }
      break;
    }
    if (worse && applied > 1.0 / 64) {
      // The step made things worse (the contact sets it assumed changed under it): half of it
      // back, and look again.
      for (std::size_t at = 0; at < nc * count; ++at) c.back[at] = -0.5 * applied * c.step[at];
      applied *= 0.5;
      shift_gaps(c.back);
      for (std::size_t at = 0; at < nc * count; ++at) c.shift[at] += c.back[at];
      warm_from_last_solve();
      r = solver->Solve(sections, freedom_, r.next, c.section_shift, kHandoff);
      continue;
    }
    last_residual = residual;
    applied = 1.0;
    // Newton's method on x = M a(x), x the sections' shifts and a their pressure amplitudes
    // (component-major): (I - M J) dx = M a(x_k) - x_k, with M the rows' coupling mapped onto the
    // sections, per part and mode M(s, t) = sum over the rows u of s and v of t of
    // (overlap_su / length_s) X(u, v) (overlap_tv / length_v), and J = da/dx at the sections'
    // contact sets (below). The contact sets move with the shifts, so a step that makes the
    // residual worse is halved (a line search on |x - M a(x)|), down to a 64th.
    CouplingSystem& system = c.newton;
    if (!coupling_built) {
      // M depends only on the sections' covers, fixed for this solve: built at its first step.
      std::vector<int> component_mode(nc);
      for (std::size_t comp = 0; comp < nc; ++comp) {
        component_mode[comp] = static_cast<int>(mode_of(comp));
      }
      system.Reset(m, std::move(component_mode));
      for (std::size_t mode = 0; mode < modes; ++mode) {
        Eigen::MatrixXd& coupling = system.mode_coupling(static_cast<int>(mode));
        coupling.setZero(m, m);
        for (Eigen::Index t = 0; t < m; ++t) {
          const auto tu = static_cast<std::size_t>(t);
          for (int q = 0; q < 2; ++q) {
            const CouplingScratch::Part& part = c.part[static_cast<std::size_t>(q)];
            const Eigen::MatrixXd& x = (*part_modes[static_cast<std::size_t>(q)])[mode].matrix();
            for (std::size_t qt = part.first[tu]; qt < part.first[tu + 1]; ++qt) {
              const int v = part.cover[qt].first;
              const double wt =
                  part.cover[qt].second / row_length(*rows[static_cast<std::size_t>(q)], v);
              for (Eigen::Index s = 0; s < m; ++s) {
                const auto su = static_cast<std::size_t>(s);
                double sum = 0.0;
                for (std::size_t qs = part.first[su]; qs < part.first[su + 1]; ++qs) {
                  sum += part.cover[qs].second * x(part.cover[qs].first, v);
                }
                coupling(s, t) += sum / length[su] * wt;
              }
            }
          }
        }
      }
      coupling_built = true;
    }
    // J = da/dx: each section's own, -w R_BB (its contact set's stiffness on the shift's
    // components, w the amplitudes' weights), plus what the part's offset and tilt do in answer,
    // which moves every section: H dq = sum_t A_t P_t^T R_UB,t dx_t (H the sections' stiffness
    // on q, P_t = [I, y_t I] the section's offset per pose), each section's amplitudes then moving
    // by w R_BU,s P_s dq. So I - M J = I + M diag(w R_BB) - (M L) H^-1 Q.
    const int dofs = freedom_.tilt ? 4 : 2;
    const auto n_all = static_cast<Eigen::Index>(nc * count);
    Eigen::MatrixXd& pose_out = system.pose_out();  // L: amplitudes per pose step
    pose_out.setZero(n_all, dofs);
    Eigen::MatrixXd pose_in = Eigen::MatrixXd::Zero(dofs, n_all);  // Q: pose forces per shift
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
    const auto ncx = static_cast<Eigen::Index>(nc);
    for (std::size_t t = 0; t < count; ++t) {
      const Eigen::MatrixXd r_t = solver->ShiftStiffness(t);
      const auto ti = static_cast<Eigen::Index>(t);
      const Eigen::MatrixXd place = SectionPlacement(sections[t], freedom_);  // P_t
      const double area = sections[t].cell_area;
      h += area * place.transpose() * r_t.bottomRightCorner(2, 2) * place;
      const Eigen::MatrixXd bu = w.asDiagonal() * r_t.topRightCorner(ncx, 2) * place;
      const Eigen::MatrixXd ub = area * place.transpose() * r_t.bottomLeftCorner(2, ncx);
      system.response(ti) = w.asDiagonal() * r_t.topLeftCorner(ncx, ncx);
      for (Eigen::Index comp = 0; comp < ncx; ++comp) {
        pose_out.row(comp * m + ti) = bu.row(comp);
        pose_in.col(comp * m + ti) = ub.col(comp);
      }
    }
    if (dofs == 4) h.bottomRightCorner<2, 2>().diagonal().array() += freedom_.tilt_stiffness;
    if (h.trace() > 0.0) {
      system.PoseCoupled();
      system.pose_in() = LeastNormSolveColumns(h, pose_in);
    } else {
      pose_out.resize(0, 0);  // nothing touches: the pose has no stiffness to answer with
    }
    const Eigen::VectorXd rhs = Eigen::Map<const Eigen::VectorXd>(c.target.data(), n_all) -
                                Eigen::Map<const Eigen::VectorXd>(c.shift.data(), n_all);
    // An inexact Newton step: solved to the iteration's own relative tolerance, it leaves a
    // thousandth of the residual it is given, below the tolerance from any start; solved to 1e-6
    // it takes twice the BiCGSTAB iterations (the pin: 10.5 a solve, not 5.0; H7/n6: 19, not 9.2)
    // for axial forces that differ by 5e-5 (the pin) and 1e-5 (H7/n6) of themselves.
    Eigen::Map<Eigen::VectorXd>(c.step.data(), n_all) = system.Solve(rhs, kShiftTolerance);
    shift_gaps(c.step);
    for (std::size_t at = 0; at < nc * count; ++at) c.shift[at] += c.step[at];
    // In contact all round the step is exact without a solve (linear: the pressures move by
    // -G^-1 B dx, the part's offset and tilt by what order 1's net forces ask), unless a pressure
    // would turn negative; the next pass checks the shifts against it.
    if (all_round != 0 && r.converged &&
        solver->ShiftFullContact(sections, freedom_, c.section_shift, &r)) {
      continue;
    }
    // The part's offset and tilt answer the step too (dq = H^-1 Q dx, the J above): the next
    // solve starts from there, not from the rigid step's point at the old gaps (the pin's contact
    // evaluations 492 instead of 649, an H7/n6's 927 instead of 1051).
    Eigen::Vector4d next = r.next;
    if (pose_out.size() > 0) {
      next.head(dofs) += system.pose_in() * Eigen::Map<const Eigen::VectorXd>(c.step.data(), n_all);
    }
    warm_from_last_solve();
    r = solver->Solve(sections, freedom_, next, c.section_shift, kHandoff);
  }
  return r;
}

bool CylinderContactAnalyzer::PressureMap(const MatingPose& pose, Eigen::VectorXd* pressure) const {
  if (!elastic_ || pressure == nullptr) return false;
  if (!pose.offset.allFinite()) throw UserError("pressure map of a non-finite axis offset");
  pressure->setZero(static_cast<Eigen::Index>(shaft_rows_) * n_);
  std::size_t k = 0;
  double t = 0.0;
  if (!Locate(pose.depth, &k, &t)) return true;
  // The sections the tables solve: where a shaft row meets a bore row.
  std::vector<Slice> slices;
  SlicesAt(pose.depth, &slices);
  if (slices.empty()) return true;
  const std::size_t n = static_cast<std::size_t>(n_), ne = n / static_cast<std::size_t>(block_);
  const std::size_t count = slices.size();
  std::vector<int> shaft_rows(count);
  std::vector<double> gaps(count * ne, 0.0), lengths(count), starts(count);
  std::vector<ContactSection> sections(count);
  const double lo = std::max(pose.depth - shaft_length_, 0.0);
  double pos = lo, engaged = 0.0;
  for (const Slice& sl : slices) engaged += sl.length;
  for (std::size_t s = 0; s < count; ++s) {
    const Slice& sl = slices[s];
    shaft_rows[s] = sl.shaft_row;
    lengths[s] = sl.length;
    starts[s] = pos;
    const auto i = static_cast<std::size_t>(sl.shaft_row);
    const double share = sl.length / (shaft_edges_[i + 1] - shaft_edges_[i]);
    SolveGaps(sl, gaps.data() + s * ne);
    sections[s].gap = gaps.data() + s * ne;
    sections[s].cell_area = shaft_area_[sl.shaft_row * n_] * share * block_;
    sections[s].y = pos + 0.5 * sl.length - (lo + 0.5 * engaged);
    pos += sl.length;
  }
  const std::size_t nearest = t < 0.5 ? k : k + 1;
  Eigen::Vector4d warm;
  warm << Rotate(anchor_[nearest], -frame_), Rotate(tilt_[nearest], -frame_);
  RigidSectionContact solver(section_, static_cast<int>(ne), coupled_orders_);
  CouplingScratch coupling;
  // The parts' elements, solved here where no depth step of the tables needed them.
  std::vector<AxialCoupling> hub, shaft;
  PartModes part_modes{&hub_modes_, &shaft_modes_};
  if (axial_coupling_ && hub_modes_.empty()) {
    SolvePartModes(&hub, &shaft);
    part_modes = {&hub, &shaft};
  }
  SolveSections(&solver, sections, starts, lengths, pose.depth - shaft_length_, gaps.data(), warm,
                &coupling, part_modes);
  // A shaft row's cells take the length-weighted mean of its sections' pressures.
  for (std::size_t s = 0; s < count; ++s) {
    const auto i = static_cast<std::size_t>(shaft_rows[s]);
    const double share = lengths[s] / (shaft_edges_[i + 1] - shaft_edges_[i]);
    for (std::size_t j = 0; j < n; ++j) {
      (*pressure)[shaft_rows[s] * n_ + static_cast<Eigen::Index>(j)] +=
          share * solver.pressures()[s * ne + j / static_cast<std::size_t>(block_)];
    }
  }
  return true;
}

// The tabulated polygon of the nearer depth step: what the tick interpolates between.
bool CylinderContactAnalyzer::DoAssemblySpace(const MatingPose& pose,
                                              std::vector<Eigen::Vector2d>* polygon) const {
  std::size_t k = 0;
  double t = 0.0;
  if (!Locate(pose.depth, &k, &t)) return true;
  if (t >= 0.5) ++k;
  if (unconstrained_[k] || empty_[k]) return true;
  const auto begin = vertices_.begin() + vertex_begin_[k];
  polygon->assign(begin, begin + vertex_count_[k]);
  return true;
}

}  // namespace fitfeel::cylindrical
