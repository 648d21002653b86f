#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/model/process_spec.h"

namespace fitfeel {

struct MeasuredSurface;

// Which side of the mating pair a part is. The tolerance space is S_T = V_outer - V_inner.
enum class Role { kInner, kOuter };  // shaft / key / pin / ball ; bushing / keyway / hole / socket

// Size limits of a feature of size, as deviations from the nominal size (ISO 286 convention:
// es/ei for shafts, ES/EI for holes). All in metres.
struct SizeSpec {
  double nominal = 0.0;
  double lower_deviation = 0.0;
  double upper_deviation = 0.0;
  std::string iso_code;  // "H7", "g6", "M10x1.5 6g" when given as a code; empty for deviations
  // An ISO metric thread (iso_code "M10x1.5 6g"): nominal is d, the deviations above are the
  // pitch diameter's from the basic d2 (ISO 965-1, what a thread surface draws its size in), and
  // these are the pitch, m, and the crest diameter's deviations, m: the bolt's major diameter
  // from d, the nut's minor diameter from the basic D1. pitch == 0 for a plain size.
  double pitch = 0.0;
  double crest_lower_deviation = 0.0;
  double crest_upper_deviation = 0.0;
  // The middle of the size zone (what a typical part of the population measures), m.
  double mid_size() const { return nominal + 0.5 * (lower_deviation + upper_deviation); }
};

// GPS form (and pair orientation) characteristics a surface type may support (paper Table 1).
enum class FormCharacteristic {
  kAxisStraightness,
  kGeneratrixStraightness,
  kRoundness,
  kCylindricity,
  kStraightness,  // line straightness of a flat face
  kFlatness,
  kParallelism,  // of a pair of flat faces
  kSphericity,
};

// Scenario spelling of a characteristic ("axis_straightness", ...).
FITFEEL_API std::string ToString(FormCharacteristic characteristic);

// Tolerance zone widths in metres, one per characteristic given.
struct FormSpec {
  std::map<FormCharacteristic, double> tolerance;
  // Characteristics a surface type declares beyond ISO 1101's (SurfaceType::
  // declared_characteristics, e.g. a thread's pitch deviation), by name, in SI units; zero when
  // the scenario does not give them.
  std::map<std::string, double> declared;
  double Get(FormCharacteristic c) const {
    auto it = tolerance.find(c);
    return it == tolerance.end() ? 0.0 : it->second;
  }
  double Declared(const std::string& name) const {
    auto it = declared.find(name);
    return it == declared.end() ? 0.0 : it->second;
  }
};

// Surface texture (paper eq. 6): waviness amplitude A, roughness Ra and Rz, in metres.
struct TextureSpec {
  double waviness = 0.0;
  double ra = 0.0;
  double rz = 0.0;
};

struct Material {
  std::string name;
  double youngs_modulus = 0.0;  // Pa
  double poisson = 0.0;
  // Yield strength R_e (or R_p0.2), Pa, for the elastic-limit check (DIN 7190); 0 = not given,
  // no check.
  double yield_strength = 0.0;
};

// The Poisson's ratios every resistance law accepts and the scenario parser admits: one range, so
// that a scene `validate` accepts is never refused by a law. Machined metals, ceramics and
// polymers lie in [0.1, 0.45]. At 0.5 (incompressible) the Lame and plane-strain compliances
// degenerate, and negative ratios belong to engineered auxetic foams, not to machined parts.
inline constexpr double kMinPoisson = 0.0;  // inclusive
inline constexpr double kMaxPoisson = 0.5;  // exclusive
inline bool PoissonInRange(double nu) { return nu >= kMinPoisson && nu < kMaxPoisson; }

// Surface-type-specific nominal geometry of one part's mating surface; each surface plugin derives
// its own and parses it from the part's `geometry` node.
class FITFEEL_API Geometry {
 public:
  virtual ~Geometry();
  // Nominal area of the mating surface that carries a skin model shape, m^2 (finite, >= 0).
  double nominal_area() const;
  // Length of the mating surface along the direction of the constrained motion, m (finite,
  // >= 0).
  double mating_length() const;
  // One line for summaries, e.g. "cylinder d=20 mm l=40 mm".
  std::string Describe() const;
  // Advance along the axis per turn of a screw (a thread's lead), m (finite, >= 0); 0 for a
  // surface whose constrained motion is a slide or a rotation alone.
  double lead() const;

 protected:
  virtual double DoNominalArea() const = 0;
  virtual double DoMatingLength() const = 0;
  virtual std::string DoDescribe() const = 0;
  // Default: 0 (no screw).
  virtual double DoLead() const;
};

// Everything the scenario says about one part.
struct PartSpec {
  std::string name;
  Role role = Role::kInner;
  SizeSpec size;
  FormSpec form;
  TextureSpec texture;
  Material material;
  std::shared_ptr<const Geometry> geometry;
  ProcessSpec process;  // how the part's size and form are spread (paper: uniform)
  // A part measured instead of drawn (docs/measured-parts.md); null: generated.
  std::shared_ptr<const MeasuredSurface> measured;
};

}  // namespace fitfeel
