#pragma once

#include "framework/model/resistance_law.h"

namespace fitfeel::planar {

// Elastic model of a key (or square shaft) compressed between two opposite walls (README.md).
//
// Two compliances in series, per unit area of flank (m/Pa):
//  - the key as an elastic block compressed across its width b in plane strain (long along y, so
//    its length cannot stretch; free to bulge in height): c_key = b (1 - nu1^2) / E1;
//  - each wall as an elastic half-space loaded uniformly over the contact strip h x L (the mean
//    surface displacement of Boussinesq's solution): c_wall = (1 - nu2^2) J(h, L) / (pi E2 h L),
//    J(a, b) = the integral of 1/|r - r'| over the rectangle twice
//            = 2/3 (a^3 + b^3 - d^3) + 2 a b (a asinh(b/a) + b asinh(a/b)),  d = sqrt(a^2 + b^2).
//    (For a square J/(a^2 sqrt(a^2)) = 2.97, i.e. Timoshenko's 0.95 factor of a flexible square
//    footing.) The walls of a keyway or square hole are backed by the whole shaft or hub, deep
//    compared with a flank height of a few millimetres: a half-space, not a thin layer.
// A uniform interference delta per face (half-size convention: the key is 2 delta wider than the
// gap) closes 2 delta across key + two walls, so
//     p = 2 delta / (c_key + 2 c_wall),
// and the press-in friction over both flanks of engaged length L is F = mu * 2 * p * h * L.
double BlockCompliance(double width, double youngs_modulus, double poisson);
double RectangleSelfPotential(double a, double b);  // J(a, b), m^3
double HalfSpaceStripCompliance(double height, double length, double youngs_modulus,
                                double poisson);
// Pressure per unit local interference (Pa/m): p = P * delta, P = 2 / (c_key + 2 c_wall).
double PressurePerInterference(double width, double height, double length, double e_key,
                               double nu_key, double e_wall, double nu_wall);

// The planar law (paper eqs. 9-12 with the elastic model above):
//  - lateral: a spring k on the distance of the part from its anchor (the assembly space's
//    nearest point, or the balance position under interference), along minus the analyzer's
//    penetration_direction (eq. 9 in one or two axes). With k = 0 (`contact_stiffness: auto`)
//    it is the walls' stiffness: a key moved sideways by e translates as a whole (its own width
//    is not compressed further), so each wall it presses on resists with area / c_wall(L):
//    k = 2 A / c_wall with both flanks pressed (under interference), A / c_wall with one
//    (resting on a flank in clearance), A the area of one face. Against the series value
//    P(L) A = 2 A / (c_key + 2 c_wall) of one face, the pair is 2 + c_key / c_wall times stiffer
//    (3.2 for the 8 x 7 key: the paper's reading of k_p as one face's stiffness is that low).
//  - normal force on the faces, once: under interference the flanks carry sum p ds = P(L) * V
//    (V the analyzer's interference volume, eq. 11); a lateral offset from the balance position
//    loads one flank and unloads the other by the same amount, so the sum does not change while
//    both are pressed. In clearance the part rests on a flank with the lateral force (plus the
//    texture's expected interference, tabulated apart). (The paper's eq. 12 adds the lateral
//    force under interference too, counting the walls twice.)
//  - axial friction: stick-slip on the depth with the run's state (framework/model/friction.h);
//    without state the smoothed kinetic law mu_k N tanh(v_y / v_s).
// Each term vanishes where the other case of the paper applies; the force is continuous.
class PlanarGpsLaw final : public ResistanceLaw {
 public:
  double PressurePerInterferenceAt(double engaged_length) const noexcept;
  // Lateral stiffness of the pair with `faces_pressed` (1 or 2) walls pressed, at the engaged
  // length and the area of one face, N/m (the auto contact stiffness).
  double LateralStiffness(double engaged_length, double face_area, int faces_pressed) const noexcept;

 protected:
  // P at full engagement (the shorter part's length engaged): the model's pressure per
  // interference depends on the engaged length L through the walls' half-space compliance, so a
  // single coefficient exists only for one L; pressure maps are drawn with the fully engaged one.
  // At partial engagement the walls are stiffer per unit area and P is higher (for the 8 x 2.6 mm
  // key of scenarios/key-parallel.yaml, +26 % at L = 10 mm, +64 % at L = 2.5 mm).
  double DoPressurePerInterference() const override;
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;
  void DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                           LawState* state, Wrench* out) const noexcept override;

 private:
  // Lateral force into `out`; returns the normal force on the faces.
  double Normal(const ContactState& contact, Wrench* out) const noexcept;
  // The torque about the mating axis of the lateral push `out` holds, for a part twisted by
  // `twist` about the axis: the push acts off the face's centre, towards the edge the twist
  // swings into the wall (PlanarContactAnalyzer narrows the faces' interval by that reach).
  void AddTwistTorque(const ContactState& contact, double twist, Wrench* out) const noexcept;
  double WallCompliance(double engaged_length) const noexcept;

  StickSlipFriction friction_;
  double stiffness_ = 0.0;
  double c_key_ = 0.0;
  double height_ = 0.0;
  double wall_factor_ = 0.0;  // (1 - nu2^2) / (pi E2)
  int faces_ = 2;
  double full_length_ = 0.0;  // engaged length at full engagement, m
};

}  // namespace fitfeel::planar
