#pragma once

#include <array>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"
#include "framework/collision/lead_in.h"
#include "framework/runtime/stage.h"

namespace fitfeel {

// One mating feature of a joint, as the joint stage reads it: its prepared analyzer and law, the
// side of it on the moving body, and where its axis lies on each body in the joint frame (the
// fixed body's, y along the insertion; the moving body at zero offset and twist), deviations
// drawn within their position tolerances included.
struct JointFeature {
  const ContactAnalyzer* analyzer = nullptr;
  const ResistanceLaw* law = nullptr;
  Role moving = Role::kInner;
  Eigen::Vector2d moving_axis{0.0, 0.0};  // (x, z), m
  Eigen::Vector2d fixed_axis{0.0, 0.0};   // (x, z), m
  double angle = 0.0;                     // the feature's frame turned about y, rad
  double engages_after = 0.0;             // joint depth at which the feature's depth is 0, m
  // A feature after the datum: its chamfers and entrance face, met before its surfaces overlap
  // (PushOfLeadIn), and the stiffness they are rendered with (N/m; 0: not rendered). The datum's
  // lead-in is the positioning stage's.
  LeadIn lead_in;
  double lead_in_stiffness = 0.0;
};

// Mating over several features at once (docs/assemblies.md): the moving body's pose (depth along
// the joint's axis, offset across it, twist about it) gives each feature its own mating pose;
// each feature's analyzer and law give its wrench, and the body's free degrees of freedom (the
// offset under the scene's load or the hand's coupling spring, the twist where the rotation is
// free) settle where the summed wrench, the load and the applied torque balance. A robot holds the
// offset where the device puts it (radial: held) or lets it settle under the load (quasi-static);
// a hand at a haptic device (finite proxy stiffness) couples the body to the device across the
// axis by that spring, as the one-feature god object does. The depth is the device's.
//
// The balance is a damped Newton iteration on (x, z, rho theta) and a proximal term k_r (q_prev -
// q) that keeps it well posed where nothing but the load acts (clearance); once the body stops
// moving the term vanishes and the balance is exact. Its Jacobian is differenced feature by
// feature, each that pushes on its own offset into its contact, and carried through the
// feature's placement; it is kept while the same features push and its steps land. Past a kink
// where a round feature turned a corner of its assembly polygon, the step is Newton's on the
// vertex's spring. Per tick: no allocation, bounded work (kMaxIterations).
class FITFEEL_API JointStage final : public Stage {
 public:
  struct Options {
    // As ConstrainedStage::Options: the scene-frame y of joint depth 0, and the coupling spring
    // of a hand (infinite: a robot holds the body).
    double depth_origin = 0.0;
    double proxy_stiffness = std::numeric_limits<double>::infinity();
  };
  // Regula falsi steps of a hand's axial balance at most (AxialBalance).
  static constexpr int kAxialSteps = 8;
  // Newton iterations of one tick's balance at most.
  static constexpr int kMaxIterations = 8;

  // Every feature's analyzer and law must be prepared and outlive the stage (a scene joins 2 or
  // more; one alone is a feature run apart, for comparison). Throws UserError for none or more
  // than kMaxJointFeatures features, an unprepared analyzer or bad
  // options.
  JointStage(std::vector<JointFeature> features, const Options& options);
  const Options& options() const { return options_; }
  const std::vector<JointFeature>& features() const { return features_; }
  // The length that turns the twist into the balance's third coordinate (rho): the farthest
  // feature axis from the joint's, or 10 mm where all lie on it.
  double lever() const { return lever_; }

 protected:
  StageId DoId() const override { return StageId::kConstrained; }
  std::unique_ptr<StageState> DoMakeState() const override;
  void DoEvaluate(const PartState& part, StageState* state,
                  StageOutput* out) const noexcept override;

 private:
  struct Share;
  struct Sum;
  struct RunState;
  // Feature i's wrench on the moving body in the joint frame, its torque about the feature's own
  // axis, with the feature's moving axis at `relative` (x, z) from its fixed axis and the body
  // twisted by `twist`, at joint depth `depth`; with `state`, the run's stateful friction,
  // advanced. `contact`: the analyzer's answer at that pose, in the analyzer's frame (read
  // where `contact_known`, written otherwise). The wrench includes the push of the feature's
  // lead-in before its surfaces overlap; returns whether the lead-in touches.
  bool FeatureWrench(std::size_t i, const Eigen::Vector2d& relative, double twist, double depth,
                     const PartState& part, LawState* state, bool contact_known,
                     ContactState* contact, Wrench* wrench) const noexcept;
  // The summed wrench of every feature (without history) with the body at offset (x, z) = q.head(2)
  // and twist q(2) / lever, at `depth`; with `states` (one per feature), the run's stateful
  // friction, advanced, and the per-feature outputs written to `out`. Where `sum` was last
  // evaluated at q (in the same tick), its contacts serve again, uncounted.
  // A hand's body along the axis: the depth between the body's last and the device's where the
  // coupling spring's pull balances the features' axial force at the body's offset and twist `q`
  // (the last tick's), counting the features' evaluations in `*evaluations`.
  double AxialBalance(double device_depth, const Eigen::Vector3d& q, const PartState& part,
                      RunState* run, int* evaluations) const noexcept;
  void Evaluate(const Eigen::Vector3d& q, double depth, const PartState& part, LawState* states,
                Sum* sum, StageOutput* out) const noexcept;
  // Feature i's wrench (force across the axis in the joint frame, own torque) differenced
  // against its relative offset at the pose `share` was evaluated at (two evaluations, counted in
  // `evaluations`): d(force x, force z, torque) / d(relative x, z).
  Eigen::Matrix<double, 3, 2> FeatureDifferences(std::size_t i, const Share& share, double depth,
                                                 const PartState& part,
                                                 int* evaluations) const noexcept;
  // Whether feature i, whose share is `near`, lies on its assembly polygon at `w` from near's
  // relative offset: its force there is at most a tenth of near's (one evaluation, counted in
  // `evaluations`).
  bool OnPolygon(std::size_t i, const Share& near, const Eigen::Vector2d& w, double depth,
                 const PartState& part, int* evaluations) const noexcept;
  // Adds to `jacobian` the share of the derivative of the generalised force on (x, z, lever *
  // twist) that a feature whose wrench changes with its relative offset by `d_u` has at the pose
  // of `share`, carried through the feature's placement.
  void AddCarried(const Eigen::Matrix<double, 3, 2>& d_u, const Share& share,
                  Eigen::Matrix3d* jacobian) const noexcept;

  std::vector<JointFeature> features_;
  // Each feature's angle's cosine and sine.
  std::array<double, kMaxJointFeatures> feature_cos_{}, feature_sin_{};
  Options options_;
  double lever_ = 0.01;
};

}  // namespace fitfeel
