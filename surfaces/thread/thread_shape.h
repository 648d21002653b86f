#pragma once

#include <vector>

#include "framework/model/discretizer.h"
#include "framework/model/render_mesh.h"
#include "framework/model/surface_type.h"
#include "framework/model/variation_generator.h"

namespace fitfeel::thread {

// Grid of both flanks: rows along the turn angle theta over the engaged turns (uniform in theta),
// columns flank by flank (flank A first), each flank split into strips uniform in radius between
// the inner and the outer radius. A cell's area is the exact helicoid area of its (theta, r)
// rectangle, so the areas sum to the closed-form flank area. row_position is the axial position
// P theta / (2 pi) of the row's centre; column_angle is the inclination of the flank's normal
// from the radial direction in the axial plane (+(pi/2 - alpha/2) for flank A, - for flank B).
// Normals point away from the external thread's material (positive V fattens a bolt's flank and
// widens a nut's thread groove, the SkinModelShape convention).
class HelicoidDiscretizer final : public Discretizer {
 public:
  // The helix is sampled every 22.5 deg; the flank height of a few tenths of a millimetre needs
  // few strips.
  static constexpr int kAutoRowsPerTurn = 16;
  static constexpr int kAutoStripsPerFlank = 4;

 protected:
  GridShape DoShape(const PartSpec& part, const Resolution& resolution) const override;
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override;
};

// The render mesh of a helicoid grid (HelicoidDiscretizer): each cell the piece of its flank's
// helicoid between its row's turn angles theta +- dtheta / 2 and its strip's radii r +- dr / 2,
// corners in the order (theta-, r-), (theta-, r+), (theta+, r+), (theta+, r-), and the cell's
// normal as its direction. In the frames RenderMesh describes: a nut's (outer part) is its grid's,
// its entrance at y = 0; a bolt's (inner part) is its grid slid along its own helix by all its
// turns, so that its leading end lies at y = 0 and its turn angles are <= 0, the frame
// ThreadContactAnalyzer places at the pose (turned by the angle about +y, moved by the depth).
// Throws UserError for a grid that is not of two flanks.
RenderMesh HelicoidRenderMesh(const PartSpec& part, const SurfaceGrid& grid);

// What the stub can generate properly (README.md): the pitch-diameter size deviation (one draw
// per part, in the size limits, taken as the deviation of d2), the pitch deviation (one draw per
// part in +-pitch_error, accumulated along the helix from the start of the engaged length) and
// each flank's half-angle deviation (one draw per flank in +-flank_angle_error, a rotation about
// the pitch line). Each enters V as its exact displacement normal to the flank, to first order.
// No form or texture: Table 1 lists none for threads, and texture is left to the law that does
// not exist yet.
class HelicoidVariationGenerator final : public VariationGenerator {
 protected:
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode texture,
                            Rng& rng) const override;
};

// The three generated quantities, recovered from a skin model shape by a least-squares fit of
// V = a + b theta + c (r - r_pitch) per flank (exact for what the generator draws): pitch
// diameter, pitch deviation and both flanks' half-angle deviations, with their limits. All in
// metres: a half-angle deviation as the normal deviation it causes across the flank's height,
// -(tan(alpha/2 + d) - tan(alpha/2)) cos(alpha/2) (r2 - r1), a monotone function of d.
std::vector<CharacteristicCheck> EvaluateHelicoidCharacteristics(const PartSpec& part,
                                                                 const SkinModelShape& sms);

}  // namespace fitfeel::thread
