#pragma once

#include <atomic>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"
#include "framework/model/skin_model_shape.h"

namespace fitfeel {

class SharedPrepare;

// Pose of the moving part relative to the fixed one, in the fixed part's mating frame.
struct MatingPose {
  double depth = 0.0;                // insertion along the mating axis (y), m; 0 = first contact
  Eigen::Vector2d offset{0.0, 0.0};  // (x, z) offset of the moving part's axis, m
  double angle = 0.0;                // rotation about the mating axis (or the sphere centre), rad
  // The moving part's axis tilted off the mating axis: the (x, z) components of the rotation
  // vector that turns +y onto it, about the fixed part's entrance centre, rad. Read by analyzers
  // that model a tilted part (the thread's); the others take the part as aligned.
  Eigen::Vector2d tilt{0.0, 0.0};
};

// The pose a contact analyzer takes (the inner part's, in the outer part's mating frame) for the
// moving part's pose in the scene frame (positioning_stage.h): the same where the inner part
// moves. Where the outer part moves, the scene frame is the inner part's turned half a turn about
// z and the pose is the outer part's; the inner part's offset in the outer part's frame is then
// the scene's reflected in z, (x, z) -> (x, -z), at the same depth and twist (the half turn maps
// a rotation about y to its inverse, and so does inverting the pose). What the analyzer and the
// law answer in that frame (forces and torques on the inner part, directions across the axis)
// is, on the moving outer part in the scene frame, the same reflection of it. Its own inverse.
FITFEEL_API MatingPose AnalyzerPose(const MatingPose& scene_pose, Role moving) noexcept;

// What the analyzer found at one pose (paper section 3.1); read by a resistance law.
struct ContactState {
  static constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();
  bool engaged = false;         // the mating surfaces overlap axially
  bool interference = false;    // the assembly space is empty: the parts are pressed together
  double engaged_length = 0.0;  // overlap along the mating axis, m
  double engaged_area = 0.0;    // nominal area of the overlapping cells, m^2
  // Radial state (eq. 9): distance of the moving axis from the fixed axis, its direction gamma,
  // and the assembly space's extent S_A(gamma) in that direction.
  double offset_distance = 0.0;  // delta d, m
  double offset_angle = 0.0;     // gamma, rad
  double assembly_extent = 0.0;  // S_A(gamma), m (0 when the assembly space is empty)
  double penetration = 0.0;      // max(0, delta d - S_A(gamma)), m
  // Unit vector along which the moving axis has left the positions it may take (the assembly
  // space, or the energy-minimising axis position under interference); the radial spring pushes
  // back along minus it. Zero when penetration is zero. An assembly space that is not centred on
  // the fixed axis is not left along gamma, so eq. 9's direction generalises to this one (and its
  // penetration to the distance from the assembly space).
  Eigen::Vector2d penetration_direction{0.0, 0.0};
  // Interference (eqs. 10-12): sum over overlapping cells of delta(P_ij) * area (m^3), with
  // texture taken as its expected interference where the settings ask for it; a law multiplies it
  // by its pressure per unit interference.
  double interference_volume = 0.0;
  double max_interference = 0.0;  // largest delta(P_ij), m
  // Resultant direction of the contact normal force in the cross-section when interfering.
  Eigen::Vector2d pressure_resultant{0.0, 0.0};  // sum of delta * area * u_j, m^3
  // d(pressure_resultant)/d(offset), m^2 (column 0 along x, 1 along z), where the analyzer gives
  // it in closed form (tabulated columns: ColumnResponseTable::Blend); NaN where it does not. A
  // law whose radial force is a linear map of the resultant turns it into its radial stiffness
  // (ResistanceLaw::RadialJacobian), which spares a settling search its differences.
  Eigen::Matrix2d resultant_jacobian = Eigen::Matrix2d::Constant(kNotGiven);
  // Models that solve the contact pressure (the cylinder's elastic model): the total normal force
  // sum p * A of the part at its equilibrium pose for this depth (N; 0 where a model does not
  // solve for pressure, or in clearance), and the equilibrium tilt of its axis (slopes dx/dy,
  // dz/dy, rad). A friction law takes its normal force from here instead of a pressure per unit
  // interference.
  double normal_force = 0.0;
  Eigen::Vector2d tilt{0.0, 0.0};
  // Contacts whose normal is not across the axis (a thread's flanks): over the interfering
  // cells, the sums of delta * area * n (m^3) and of delta * area * (p x n) (m^4, about the
  // fixed part's origin, p the cell's centre, n its unit normal out of the inner part), and the
  // same with n replaced by the unit direction in which the inner part's cell slides along the
  // fixed part under the constrained motion (a screw's helix), for friction. A law turns them
  // into the normal wrench (times its pressure per unit interference) and the friction wrench.
  // Zero where an analyzer describes its contact by the radial state above alone. Always in the
  // analyzer's frame (SceneContact leaves them): a stage that reads them maps them itself.
  Eigen::Vector3d normal_sum{0.0, 0.0, 0.0};
  Eigen::Vector3d normal_moment{0.0, 0.0, 0.0};
  Eigen::Vector3d slide_sum{0.0, 0.0, 0.0};
  Eigen::Vector3d slide_moment{0.0, 0.0, 0.0};
  // An axial stop of the pair (a nut's bearing face on the clamped part): how far the inner part
  // is past where the stop meets, m (0 before it meets).
  double stop_closure = 0.0;
  // A part held tilted by a compliant holder and forced towards the axis by two-point contact
  // (docs/tilted-parts.md): the sum of the two contacts' normal forces, N, which a law adds to
  // the normal force its friction acts on, and their couple on the part, N*m (x, z components,
  // turning it towards the axis). Zero otherwise.
  double couple_normal = 0.0;
  Eigen::Vector2d couple_moment{0.0, 0.0};
  // A progressive prepare (ContactAnalyzer::PrepareStart) that had not reached the pose's depth:
  // how far the pose is past the prepared frontier, m. Everything above is then the state at the
  // frontier, held until the tables reach the pose. Zero: the state at the pose itself.
  double held_depth = 0.0;
};

// The analyzer's answer at AnalyzerPose(pose, moving) with its directions across the axis in the
// scene frame: where the outer part moves, reflected in z as the pose was (offset angle, the
// penetration direction, the resultant, the tilt and the resultant's Jacobian); nothing otherwise.
// Its own inverse.
FITFEEL_API void SceneContact(ContactState* contact, Role moving) noexcept;

// Builds per-depth tables in prepare and answers per-tick queries in bounded time.
//
// Progressive prepare (docs/progressive-prepare.md). An analyzer that takes it
// (takes_progressive_prepare()) prepares its depth tables in depth order: PrepareStart prepares
// what does not depend on depth and the steps up to a ready depth, PrepareAhead the rest a few
// steps at a time from one other thread (the prepare's worker), or FinishPrepare all of it at
// once. Each call publishes how deep the tables are complete (prepared_depth(), release); a tick's
// Evaluate reads it (acquire) and, past it, answers the state at that depth with
// ContactState::held_depth set. The tables are the same bits however they were prepared. An
// analyzer without it prepares whole in PrepareStart.
class FITFEEL_API ContactAnalyzer {
 public:
  ContactAnalyzer() = default;
  ContactAnalyzer(const ContactAnalyzer& other);
  ContactAnalyzer& operator=(const ContactAnalyzer& other);
  virtual ~ContactAnalyzer();
  // Prepare-time; may allocate.
  void Prepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
               const SkinModelShape& outer_sms, const ModelSettings& settings);
  // The same, taking from `shared` (and leaving there) what depends only on the scene, for the
  // other prepares of runs of the same scene (a study's pairs); null: nothing shared. The
  // analyzer keeps no reference to it: its tables are its own either way, bit for bit the same.
  void Prepare(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
               const SkinModelShape& outer_sms, const ModelSettings& settings,
               SharedPrepare* shared);
  // The progressive prepare's start: what does not depend on depth and the depth steps up to
  // `ready_depth` (m past first contact), on the calling thread; an analyzer that does not take
  // it prepares whole. `shared` (may be null) must outlive the prepare's last call. Evaluate
  // answers once it returns.
  void PrepareStart(const PartSpec& inner, const SkinModelShape& inner_sms, const PartSpec& outer,
                    const SkinModelShape& outer_sms, const ModelSettings& settings,
                    SharedPrepare* shared, double ready_depth);
  // After PrepareStart, from one thread at a time while ticks may Evaluate on others: prepares up
  // to `steps` more depth steps in depth order and publishes them. False once the tables are
  // whole (then nothing is left to do).
  bool PrepareAhead(int steps);
  // After PrepareStart, on one thread while no PrepareAhead runs: prepares the rest of the
  // tables, with the prepare's threads where the analyzer parallelises.
  void FinishPrepare();
  // How deep the tables are complete, m: Evaluate answers exactly up to here and holds the state
  // here past it. +inf once whole. Safe from any thread.
  double prepared_depth() const { return prepared_depth_.load(std::memory_order_acquire); }
  bool takes_progressive_prepare() const { return DoTakesProgressivePrepare(); }
  // Per tick: no allocation, no locks, no exceptions, no I/O. Past prepared_depth(): the state at
  // that depth, with ContactState::held_depth the distance past it.
  void Evaluate(const MatingPose& pose, ContactState* out) const noexcept;
  bool prepared() const { return prepared_; }
  // Whether the analyzer models a part held tilted (ModelSettings::held_tilt, or MatingPose::tilt
  // per tick); false (the default): it takes the part as aligned, and a scene that tilts it is
  // refused.
  bool takes_held_tilt() const { return DoTakesHeldTilt(); }
  // Whether it models a compliant holder's tilt (a finite ModelSettings::held_tilt_stiffness);
  // false (the default): a scene that gives one is refused.
  bool takes_compliant_tilt() const { return DoTakesCompliantTilt(); }
  // Not for the tick (may allocate): the interference delta(P_ij) >= 0 of every cell of the inner
  // part's grid at `pose` (zero where there is clearance), for pressure maps and pictures.
  void InterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const;
  // Not for the tick (may allocate): the assembly space of the cross-sections engaged at `pose`
  // (paper section 3.1), the convex polygon of (x, z) positions the moving axis may take, m,
  // counter-clockwise. True when the analyzer describes it (the polygon is empty when the parts
  // interfere or are not engaged); false (the default) when this surface type does not.
  bool AssemblySpace(const MatingPose& pose, std::vector<Eigen::Vector2d>* polygon) const;

 protected:
  virtual void DoPrepare(const PartSpec& inner, const SkinModelShape& inner_sms,
                         const PartSpec& outer, const SkinModelShape& outer_sms,
                         const ModelSettings& settings) = 0;
  virtual void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept = 0;
  virtual void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const;
  virtual bool DoAssemblySpace(const MatingPose& pose, std::vector<Eigen::Vector2d>* polygon) const;
  virtual bool DoTakesHeldTilt() const { return false; }
  virtual bool DoTakesCompliantTilt() const { return false; }
  // Progressive prepare; false (the default): PrepareStart calls DoPrepare.
  virtual bool DoTakesProgressivePrepare() const { return false; }
  // What DoPrepare does but the depth steps; publishes prepared_depth() (the depth its tables are
  // complete to, with none of them prepared). Called only where DoTakesProgressivePrepare().
  virtual void DoPrepareStart(const PartSpec& inner, const SkinModelShape& inner_sms,
                              const PartSpec& outer, const SkinModelShape& outer_sms,
                              const ModelSettings& settings);
  // The next `steps` depth steps in depth order, each published as it is done (+inf after the
  // last); false once none is left.
  virtual bool DoPrepareAhead(int steps);
  // Every step left; the default calls DoPrepareAhead until none is left.
  virtual void DoFinishPrepare();
  // From DoPrepareStart, DoPrepareAhead and DoFinishPrepare: the tables are complete to `depth`
  // (m; +inf: whole), and every entry Evaluate reads up to it is written (release).
  void PublishPreparedDepth(double depth) {
    prepared_depth_.store(depth, std::memory_order_release);
  }
  // While the prepare runs (DoPrepare, or from DoPrepareStart to the last step): what this
  // prepare shares with the others of the same scene; null when it shares nothing.
  SharedPrepare* shared_prepare() const { return shared_; }

 private:
  bool prepared_ = false;
  SharedPrepare* shared_ = nullptr;  // set only while a prepare runs
  std::atomic<double> prepared_depth_{std::numeric_limits<double>::infinity()};
};

}  // namespace fitfeel
