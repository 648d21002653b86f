#pragma once

#include <array>
#include <atomic>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"
#include "framework/model/convex_polygon.h"
#include "framework/model/texture_contact.h"
#include "surfaces/cylindrical/coupling_newton.h"
#include "surfaces/cylindrical/elastic/axial_coupling.h"
#include "surfaces/cylindrical/elastic/section_contact.h"

namespace fitfeel::cylindrical {

// Contact and space analysis of a shaft (inner part, moving along +y) in a bushing (paper 3.1).
//
// Alignment. Each part's rows cover [first boundary, last boundary] along its own y (boundaries
// halfway between row centres; a one-row grid takes the part's mating length). Depth D = 0 puts
// the shaft's leading end (its largest y) at the bushing's entrance (its smallest y); at depth D a
// shaft point at distance s behind its leading end sits D - s into the bushing. The overlap is cut
// into slices at every row boundary of either part, so each slice faces exactly one shaft row and
// one bushing row: grids of different row pitch are matched through axial position, exactly for
// piecewise-constant cells (paper step 1). A slice's cell area is the shaft cell's area times the
// slice's share of the shaft row.
//
// Tables (prepare, per depth step D_k = k * step, k = 0 .. K, D_K >= L_shaft + L_bushing):
// per-angle minima h_j = min S_T over the overlapping slices (eq. 8) and the assembly-space
// polygon { p : p . u_j <= h_j } as vertices; when it is empty (interference, 3.2.2) the axis
// position p* minimising the elastic energy sum(area * delta^2) (a Winkler bed: pressure linear in
// delta, energy quadratic), found by Newton's method on that convex piecewise-quadratic function
// with a backtracking line search (exact in finitely many steps; warm-started from the previous
// depth); and at the anchor position (p* under interference, the polygon's centroid otherwise) the
// interference volume sum(area * delta), its largest delta and its resultant sum(area * delta *
// u_j), where delta is the sharp max(0, -gap), or, with TextureMode::kExpected, the expected
// interference E[(X - gap)+] of the equivalent rough-on-smooth texture (texture_contact.h).
//
// Elastic model (law `elastic`, docs/contact-mechanics.md). Where the assembly space of the
// smoothed gaps is empty, the part's equilibrium in offset and (unless fixed) tilt is solved
// against the elastic contact of every slice: non-negative pressure per column, compliance per
// circumferential harmonic (Michell; elastic/section_contact.h). The elastic solve runs on the
// grid's columns averaged in blocks to at most 120 (harmonics up to 60, waviness down to 1 mm at
// d = 20 mm). The anchor is then the equilibrium offset at the middle of the engaged
// length, and the tables add the normal force sum p A and the tilt.
//
// Per tick: linear interpolation between the two neighbouring depth steps of every tabulated
// scalar, and of the anchor points: the point the axis may take is the nearest assembly-space
// point (or p*) at each of the two steps, blended with the same weight. Forces built from it are
// continuous in depth and offset (taking the nearest step would make them jump by a whole row's
// change at each step, which a haptic device renders as a click). Cost O(vertices) <= O(n + 4),
// independent of m, with no allocation.
//
// Progressive prepare (ContactAnalyzer::PrepareStart): the steps in depth order, chunk by chunk
// from each chunk's cold start as the parallel prepare takes them, so the tables are the same bits
// either way; each step's entries are written before the step count is published, and the
// polygons' arrays are reserved for every step up front, so nothing a tick reads moves.
class CylinderContactAnalyzer final : public ContactAnalyzer {
 public:
  // Per-tick footprint: the largest vertex count of any tabulated polygon (<= n + 4).
  int max_polygon_vertices() const { return max_vertices_; }
  int depth_steps() const { return static_cast<int>(depth_.size()); }
  double depth_step() const { return step_; }
  double max_depth() const { return max_depth_; }
  // Tabulated anchor (p* or centroid) and interference flag at step k, for tests and pictures.
  // InterferenceMap maps each shaft row through its centre's axial position; the axis is at the
  // energy-minimising position under interference and at the pose's offset in clearance.
  Eigen::Vector2d anchor(int k) const { return anchor_[static_cast<std::size_t>(k)]; }
  bool interference_at(int k) const { return empty_[static_cast<std::size_t>(k)] != 0; }
  int newton_iterations() const { return newton_iterations_; }
  // Whether the last prepare solved the parts' axial elements (some depth step interfered).
  bool axial_elements_solved() const { return !hub_modes_.empty(); }
  // Elastic model (law `elastic`): equilibrium normal force and tilt at step k, the DIN 7190
  // smoothing added to every gap (texture din7190), and the columns of the elastic solve.
  bool elastic() const { return elastic_; }
  // Not for the tick (allocates and solves): the elastic model's contact pressure (Pa) of every
  // cell of the shaft's grid at the pose's depth, at the part's equilibrium: the sections where a
  // shaft row meets a bore row solved as the tables solve them, a row's cells taking the
  // length-weighted mean of its sections' pressures (zero for the part of a row outside the bore)
  // and each column block's pressure spread over its cells. False (nothing written) without the
  // elastic model.
  bool PressureMap(const MatingPose& pose, Eigen::VectorXd* pressure) const;
  double normal_force(int k) const { return normal_[static_cast<std::size_t>(k)]; }
  Eigen::Vector2d tilt(int k) const { return tilt_[static_cast<std::size_t>(k)]; }
  double smoothing() const { return smoothing_; }
  int elastic_columns() const { return elastic_ ? n_ / block_ : 0; }

 protected:
  void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                 const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  bool DoTakesProgressivePrepare() const override { return true; }
  void DoPrepareStart(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                      const SkinModelShape& outer_sms, const ModelSettings& settings) override;
  bool DoPrepareAhead(int steps) override;
  void DoFinishPrepare() override;
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override;
  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override;
  bool DoAssemblySpace(const MatingPose& pose,
                       std::vector<Eigen::Vector2d>* polygon) const override;
  // Prepared for ModelSettings::held_tilt; MatingPose::tilt is not read.
  bool DoTakesHeldTilt() const override { return true; }
  bool DoTakesCompliantTilt() const override { return true; }

 private:
  struct Slice {
    int shaft_row;
    int bushing_row;
    double length;
  };
  void SlicesAt(double depth, std::vector<Slice>* slices) const;
  // A slice's gaps on the elastic solve's columns (n / block_ values into `out`): bore less shaft
  // variation plus the smoothing, the cells' own with one column per cell, else from the parts'
  // rows on the solve's columns (OnSolveColumns).
  void SolveGaps(const Slice& slice, double* out) const;
  // A shaft row meeting a bore row at one step of a chunk, ordered for ChunkMinima's pass.
  struct RowPair {
    int block, shaft_row, step, bushing_row;  // step: index within the chunk; block: its group
    auto operator<=>(const RowPair&) const = default;
  };
  // What one thread of the prepare carries from step to step of a chunk: buffers and warm starts.
  // The parts' axial coupling of one solve, by components: the breathing mode, then cos(n theta)
  // and sin(n theta) of each coupled order (the solver's shift_basis()). Per coupling row of
  // either part and component the pressure amplitude (kept from the last solve: the next depth
  // step starts from its extra displacement) and that displacement; per section the rows it
  // covers with the overlaps' lengths; per component and section (component-major) the gap shift
  // applied, its target and the Newton step; per section the contact set to restart from; and the
  // Newton system.
  struct CouplingScratch {
    // One per part, the hub's (bore coordinates) then the shaft's.
    struct Part {
      std::vector<double> pressure, extra;        // per component, per coupling row
      std::vector<std::pair<int, double>> cover;  // per section: its rows and overlaps
      std::vector<std::size_t> first;             // where each section's cover starts
    };
    std::array<Part, 2> part;
    std::vector<double> shift, target, step, back;
    std::vector<double> best;                       // the shifts of the lowest residual so far
    std::vector<double> section_dp, section_shift;  // section-major, for the solver
    std::vector<std::vector<char>> section_contact;
    Eigen::MatrixXd weights;  // columns x components: a section's pressures to its amplitudes
    CouplingSystem newton;
  };
  // The hub's and the shaft's elements per coupled mode (the breathing mode, then each order of
  // coupled_orders_), solved (EnsurePartModes, or the caller's own).
  using PartModes = std::array<const std::vector<AxialCoupling>*, 2>;
  // The sections' solve with the parts' axial coupling (axial_coupling_ set): each section's gaps
  // (`gaps`, section-major, the solver's columns each) are shifted by the extra displacement of
  // the coupling rows it covers in either part for the rows' pressure amplitudes until they agree
  // (Newton's method on the sections' exact contact-set response and the part's pose, with a
  // line search; in contact all round a step is exact without a solve).
  // Per section its start along the bore (bushing coordinates) and length; `shift` is the
  // bushing coordinate of the shaft's coordinate 0 (depth - shaft length).
  RigidContactResult SolveSections(RigidSectionContact* solver, std::span<ContactSection> sections,
                                   std::span<const double> start, std::span<const double> length,
                                   double shift, double* gaps, const Eigen::Vector4d& warm,
                                   CouplingScratch* scratch, const PartModes& part_modes) const;
  // Both parts' elements from their bodies and coupling rows, one per coupled mode.
  void SolvePartModes(std::vector<AxialCoupling>* hub, std::vector<AxialCoupling>* shaft) const;
  // Solves them into the analyzer once, for the first depth step whose sections need them (any
  // thread of the prepare's; the others wait).
  void EnsurePartModes();

  struct StepScratch {
    std::vector<std::vector<Slice>> chunk_slices;  // per step of the chunk
    std::vector<double> chunk_h;  // per step of the chunk: the smallest gap of each column
    std::vector<RowPair> pairs, sorted_pairs;
    std::vector<std::size_t> bucket;
    std::vector<double> st, w, col_a, col_b, col_energy, proj, elastic_gap;
    std::vector<ContactSection> sections;
    std::vector<double> section_start, section_length;
    Eigen::Vector2d warm{0.0, 0.0};
    Eigen::Vector4d elastic_warm = Eigen::Vector4d::Zero();  // in the elastic solve's frame
    std::optional<RigidSectionContact> solver;
    // The contact set each bore row had at the last depth step that engaged it: one step deeper
    // the row meets the same or the next shaft row a fraction of a row further on, and its
    // contact set is mostly the same, so the section's LCP starts there instead of from the
    // interference set. And its factorizations: they depend only on the contact set, so the
    // row's last ones are the cheapest start for its next (updated by rows where the set changed
    // a little).
    std::vector<std::vector<char>> row_contact;
    std::vector<std::size_t> row_contact_step;
    std::vector<CirculantContact::Factorization> row_factors;
    int newton_iterations = 0;
    CouplingScratch coupling;
    // A chunk's cold start: no warm starts, buffers sized for `columns`.
    void Restart(std::size_t columns, std::size_t bore_rows);
  };
  // One step's assembly-space polygon and its fans' angles, joined in step order after the loop.
  struct StepPolygon {
    std::vector<Eigen::Vector2d> vertices;
    std::vector<double> centre_angles, origin_angles;
  };
  // Step k's polygon appended to the tables' vertex arrays (steps join in depth order).
  void JoinPolygon(std::size_t k, const StepPolygon& polygon);
  // Steps 0 .. steps - 1 are written: publishes them and the depth they interpolate to.
  void PublishSteps(std::size_t steps);
  // Per column, the lateral slope of a part tilted by `rotation` (x, z of its rotation vector)
  // along the column's direction.
  std::vector<double> ColumnSlopes(const Eigen::Vector2d& rotation) const;
  // The smallest gap per column (into h, n values, min-ed with what is there) over `slices` at
  // `depth` of a part tilted with column slopes `kappa`: each slice's gaps widened by its distance
  // behind the leading end, at the slice's end where that is least.
  void TiltedMinima(double depth, const std::vector<Slice>& slices,
                    const std::vector<double>& kappa, double* h) const;
  // Whether a part tilted with column slopes `kappa` fits laterally nowhere with its leading end
  // at `depth` (the assembly space is empty). Prepare-time.
  bool TiltedSpaceEmpty(double depth, const std::vector<double>& kappa) const;
  // The depth at which a part tilted with column slopes `kappa` first stops fitting (two-point
  // contact), to within a micrometre; the largest depth when it never does.
  double TwoPointDepth(const std::vector<double>& kappa) const;
  // ChunkMinima for a part held tilted: each slice's gaps widened by its distance behind the
  // leading end (kappa_), at the slice's end where that is least.
  void TiltedChunkMinima(std::size_t first, std::size_t end, StepScratch* scratch) const;
  // The slices and per-column smallest gaps of steps [first, end) into the scratch.
  void ChunkMinima(std::size_t first, std::size_t end, StepScratch* scratch) const;
  // Fills every table entry of depth step k, step t of the scratch's chunk (distinct entries per
  // step: safe across threads).
  void PrepareStep(std::size_t k, std::size_t t, StepScratch* scratch, StepPolygon* polygon);
  // The sharp-contact energy of the GPS law's equilibrium at offset p over the step's cells; its
  // per-column moments (the Newton step's gradient and Hessian) in the scratch's col_a, col_b.
  double Energy(const Eigen::Vector2d& p, StepScratch* scratch) const;
  // Anchor of step k for an axis at x: where the spring of eq. 9 / 12 pulls it.
  Eigen::Vector2d AnchorAt(std::size_t k, const Eigen::Vector2d& x) const noexcept;
  // Interpolation position of a depth: step index k (< K) and weight t of step k + 1.
  bool Locate(double depth, std::size_t* k, double* t) const noexcept;

  // Inputs kept for slicing and the interference map.
  int n_ = 0;
  int shaft_rows_ = 0, bushing_rows_ = 0;
  std::vector<double> shaft_edges_;    // a_i: row boundaries from the shaft's trailing end, m
  std::vector<double> bushing_edges_;  // c_k: row boundaries from the bushing's entrance, m
  double shaft_length_ = 0.0, bushing_length_ = 0.0;
  Eigen::VectorXd v_shaft_, v_bushing_, shaft_area_;
  std::vector<double> shaft_row_area_;  // sum of each shaft row's cell areas, m^2
  Eigen::VectorXd shaft_row_centre_;    // from the shaft's trailing end, m
  std::vector<double> cos_, sin_, angle_;
  HalfPlanes half_planes_;  // the columns' constraints of the assembly space (eq. 8)
  ExpectedInterferenceTable texture_;

  // Tables, one entry per depth step.
  double step_ = 0.0, max_depth_ = 0.0;
  std::vector<double> depth_, length_, area_, volume_, max_delta_;
  std::vector<Eigen::Vector2d> resultant_, anchor_;
  std::vector<char> empty_, unconstrained_;
  std::vector<int> vertex_begin_, vertex_count_;
  std::vector<Eigen::Vector2d> vertices_;
  // Per depth step, the polygon's fans (convex_polygon.h) about its centroid, anchor_[k] (for
  // the anchor), and about the origin (for the assembly extent); angles indexed as vertices_,
  // meaningful only where the step's flag says the fan is valid.
  std::vector<double> centre_angles_, origin_angles_;
  std::vector<char> centre_fan_, origin_fan_;
  int max_vertices_ = 0;
  int newton_iterations_ = 0;
  // The steps prepared so far (the prepare's thread writes, a tick reads: release / acquire),
  // the next one to prepare, and what the progressive prepare carries from step to step of a
  // chunk. The elastic solver every thread of the prepare copies.
  std::atomic<std::size_t> prepared_steps_{0};
  std::size_t next_step_ = 0;
  StepScratch step_scratch_;
  StepPolygon step_polygon_;
  std::optional<RigidSectionContact> solver_;

  // Elastic model.
  bool elastic_ = false;
  int block_ = 1;           // grid columns averaged into one column of the elastic solve
  double smoothing_ = 0.0;  // m, added to every gap
  // A part held tilted (ModelSettings::held_tilt): per column, how far the axis moves towards
  // that column per metre of depth (the axis's lateral slope dotted with the column's
  // direction). A shaft point s behind the leading end sits s * kappa_[j] less towards column j
  // than the leading end, so its gap there grows by that much: the tables hold the leading end's
  // room (pose.offset is the leading end's). Empty: aligned.
  std::vector<double> kappa_;
  // A compliant holder's tilt (finite ModelSettings::held_tilt_stiffness): the tables are the
  // aligned part's, and these give where two-point contact forces it towards the axis. For tilts
  // curve_tilt_ (ascending, the last the holder's), the leading end's depth curve_depth_ at which
  // the part so tilted stops fitting laterally (descending); the holder's stiffness, N*m/rad; and
  // the unit direction of the tilt's rotation vector (x, z).
  std::vector<double> curve_tilt_, curve_depth_;
  double hold_stiffness_ = 0.0;
  Eigen::Vector2d hold_axis_{0.0, 0.0};
  PressFitSection section_;
  // The hub's and the shaft's deformation along their axes: with the axial coupling, the bodies
  // and, once a depth step needed them, their elements (empty: not needed yet, or plane sections).
  bool axial_coupling_ = false;
  AxialBody hub_body_, shaft_body_;
  std::vector<AxialCoupling> hub_modes_, shaft_modes_;  // per coupled mode
  // The circumferential orders (1 .. axial_orders) coupled along the axes besides the breathing
  // mode.
  std::vector<int> coupled_orders_;
  std::mutex modes_mutex_;  // prepare only: the first interfering step solves the elements
  // Their rows' edges: the grid's rows split to the shortest row of either part.
  std::vector<double> hub_coupling_rows_, shaft_coupling_rows_;
  RigidFreedom freedom_;
  double frame_ = 0.0;  // angle of the elastic solve's column 0
  // With blocks of columns (block_ > 1): each row's variation on the solve's columns, per part
  // (n / block_ x rows).
  Eigen::MatrixXd solve_shaft_, solve_bushing_;
  std::vector<double> normal_;
  std::vector<Eigen::Vector2d> tilt_;
};

}  // namespace fitfeel::cylindrical
