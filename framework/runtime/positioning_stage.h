#pragma once

#include <memory>

#include "framework/collision/coarse_mesh.h"
#include "framework/collision/lead_in.h"
#include "framework/core/export.h"
#include "framework/runtime/stage.h"
#include "framework/model/gps_spec.h"

namespace fitfeel {

class MeshCollider;
class CollisionScratch;

// Frame convention of a run (shared by every stage and device): the scene frame is the fixed
// part's mating frame. y is the mating axis, pointing in the direction of insertion; the fixed
// part's entrance (its first cross-section met by the moving part) is at y = 0. A device reports
// the pose of the moving part's leading end on its axis, and the orientation whose y axis is the
// moving part's axis. The insertion depth is then the y of the leading end.

// Free motion before mating (paper section 3: "positioning stage").
//
// With a lead-in (LeadIn: a pair of revolution whose chamfers guide the part) the moving part is
// a god object, whichever part moves (below): where the lead-in lets an aligned part be, as close
// to the device as it can slide there (LeadIn::Project), and the device is pulled towards it by a
// spring of stiffness k_free; the pose the stage reports is the part's, not the device's. The
// part's orientation is the constraint's (aligned: a 3-DOF device renders no torque; a 6-DOF
// device's tilt is not rendered) and only its twist follows the device. It hands over to the
// constrained stage once the part reaches the lead-in's capture depth, the depth from which the
// reported depth is counted (the mating depth); the constrained stage continues from the part's
// pose, and hands back when the part is pulled out past it. The lead-in's free region is one of
// relative position: the inner part's tip y past the outer part's mating start, r off its axis.
// With the outer part moving, the scene frame is the inner part's turned half a turn about z
// (CoarseMeshes): its tip at y = 0, its body at y >= 0, and the device reports the outer part's
// mating start at (y, o), which then has the inner part's tip y past it and |o| off its axis: the
// (y, r) of an inner part moved to (y, o). So the same region and god object serve both roles,
// and neither queries the collider.
//
// Otherwise it collides the parts' coarse meshes (MeshCollider: meshes made of convex solids, as
// every shipped surface's are, by separating axes; others with FCL; docs/architecture.md,
// section 4: here and only here, since mesh-mesh queries between mated surfaces cost 1-35 ms) and
// renders a penalty force k_free * depth along the way out, zero when free. Hands over to the
// constrained stage once the leading end has reached the entrance (depth >= 0) with the part's axis
// aligned with the mating axis and inside the entrance's capture radius; on the hand-over tick it
// renders nothing, since inside the capture radius the entrance's edge break (which the coarse
// meshes do not model) guides the part and the constrained stage owns the contact from the next
// tick.
//
// Without coarse meshes (the default constructor, or a surface type whose MakeCoarseMeshes keeps
// the default), free motion is collision-free: the part passes through the fixed one's face.
//
// Limits: the way out is searched along a few axes (convex pieces: the overlapping pairs' summed
// and deepest axes; FCL: the normals of the first `max_contacts` triangle pairs it reports), so it
// is a translation that frees the part from what it overlaps, not always the least one: for a flat
// end on a flat face the depth is exact, across faceted walls it is exact to within the meshes'
// chordal error, and a part tilted across a bore, touching both sides, may have no way out by
// translation at all (the penalty then pushes along the best axis found). `gap` stays unknown
// (infinity): no distance query is made.
class FITFEEL_API PositioningStage final : public Stage {
 public:
  struct Options {
    // Largest tilt of the moving axis against the mating axis accepted at the hand-over. The
    // constrained model (paper eqs. 9-12) describes a part whose axis is parallel to the mating
    // axis; 1 degree is what a lead chamfer lets through on a 20 mm fit without jamming in
    // practice, and the constrained stage then ignores the residual tilt.
    double alignment_tolerance = 0.017453292519943295;  // rad (1 degree)
    // Largest radial offset of the leading end from the mating axis accepted at the hand-over: a
    // 0.5 mm x 45 degree edge break (ISO 13715's common default) guides an axis that far off into
    // the bore.
    double capture_radius = 0.5e-3;  // m
    // Stiffness k_free of the free-motion penalty, N/m (see FreeMotionStiffness). 0 renders no
    // force (the contact is still detected).
    double free_stiffness = 0.0;
    // Meshes that are not made of convex solids only (FCL): most triangle pairs one query reports
    // (its contact buffer is reserved for them). FCL's cost grows with it (positioning tick, 20 mm
    // pair, 50 facets: about 0.17 ms CPU per tick in contact at 64, 0.09 us free); 64 keeps a face
    // contact exact and a part pressed sideways into the bore within 20 degrees and one chordal
    // error of the true way out (all pairs, 256: within 2 pi / n), at a quarter of the cost of
    // enumerating them all.
    int max_contacts = 64;
  };

  // No coarse meshes: collision-free free motion.
  PositioningStage();
  // Throws UserError for a negative or non-finite option.
  explicit PositioningStage(const Options& options);
  // Builds the collider of `meshes` once (see CoarseMeshes for their frames); `moving` is the part
  // the device moves: when it is the outer one, both meshes are turned half a turn about z into
  // the scene frame. Empty meshes mean no collision. Throws UserError for bad options or a mesh
  // the collider refuses.
  PositioningStage(const Options& options, const CoarseMeshes& meshes, Role moving);
  // As above, with a lead-in, which takes the place of the meshes when it is not empty (either
  // part moving: see above).
  PositioningStage(const Options& options, const CoarseMeshes& meshes, Role moving,
                   LeadIn lead_in);
  ~PositioningStage() override;
  PositioningStage(const PositioningStage&) = delete;
  PositioningStage& operator=(const PositioningStage&) = delete;

  StageId DoId() const override { return StageId::kPositioning; }
  const Options& options() const { return options_; }
  // True when coarse meshes were given: free motion collides.
  bool collides() const { return collider_ != nullptr || !lead_in_.empty(); }
  // Empty when the stage has none (free motion then collides the meshes, if any).
  const LeadIn& lead_in() const { return lead_in_; }
  // Where mating depth 0 is in the scene frame: the lead-in's capture depth, else 0.
  double depth_origin() const { return lead_in_.empty() ? 0.0 : lead_in_.capture_depth(); }

 protected:
  // The run's state holds the collider's scratch (its buffers, reserved up front).
  std::unique_ptr<StageState> DoMakeState() const override;
  void DoEvaluate(const PartState& part, StageState* state,
                  StageOutput* out) const noexcept override;

 private:
  // The god object's tick (lead-in).
  void GuideThroughLeadIn(const PartState& held_part, StageState* state, StageOutput* out) const
      noexcept;

  Options options_;
  LeadIn lead_in_;
  double cos_alignment_tolerance_ = 1.0;
  std::unique_ptr<MeshCollider> collider_;
};

// k_free for a scene: the scenario's contact stiffness (model.contact_stiffness, the k_p of
// eq. 9, the one stiffness the scenario gives for a rigid contact), capped at the device's
// largest stable stiffness when the device states one (finite and > 0; 0 or infinity mean no
// limit): a face met in free motion is rendered as stiff as the device holds stably, never
// stiffer than the mating contact itself. A contact stiffness of 0 (`auto`: the law's own model)
// gives the device's limit, or 0 without one. Throws UserError for a negative or NaN argument or
// a non-finite contact stiffness.
FITFEEL_API double FreeMotionStiffness(double contact_stiffness, double device_max_stiffness);

}  // namespace fitfeel
