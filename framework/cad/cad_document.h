#pragma once

// What the STEP reader hands back: plain data, without any Open CASCADE type, so that it crosses
// the pipe from the reading child process as text and the checks, the feature finder and the
// scenario writer compile without OCCT's headers. Lengths in metres, in the assembly's frame.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace fitfeel::cad {

enum class SurfaceKind { kPlane, kCylinder, kCone, kSphere, kBSpline, kOther };

const char* SurfaceKindName(SurfaceKind kind);

struct CadFace {
  int entity = 0;  // the STEP entity number of its face (#entity), 0 when the reader gave none
  SurfaceKind kind = SurfaceKind::kOther;
  std::string surface_type;        // the reader's own name for kOther and kBSpline
  std::array<double, 3> origin{};  // on the axis (cylinder, cone, sphere: centre), or the plane
  std::array<double, 3> axis{0, 0, 1};  // unit; the plane's normal
  double radius = 0.0;                  // cylinder, sphere; the cone's at `origin`
  double semi_angle = 0.0;              // cone, rad
  double axial_min = 0.0;               // extent along `axis` from `origin`
  double axial_max = 0.0;
  // Whether the face's outward normal (away from the material) points away from the axis: a
  // shaft's face, not a hole's. Meaningful for cylinders, cones and spheres.
  bool convex = false;
  // A few points of the face (B-spline faces only), to tell whether it sits on a mating
  // cylinder of the other part.
  std::vector<std::array<double, 3>> samples;
};

enum class ToleranceKind {
  kSize,
  kRoundness,
  kCylindricity,
  kStraightness,
  kFlatness,
  kOther,  // read and listed, not used
};

const char* ToleranceKindName(ToleranceKind kind);

// One semantic PMI item as the reader gives it, unchecked. Values in metres.
struct CadTolerance {
  ToleranceKind kind = ToleranceKind::kOther;
  std::string type;        // the reader's name of its type (for kOther and messages)
  std::vector<int> faces;  // entity numbers of the faces it applies to
  double value = 0.0;      // a size's nominal; a geometric tolerance's zone width
  bool has_plus_minus = false;
  double lower = 0.0;      // deviations
  bool has_range = false;  // limits given as a range: lower and upper sizes
  double upper = 0.0;
  std::string iso_class;    // "H7" when the dimension carries a class of tolerance
  bool hole_class = false;  // the class's hole flag as the file states it
};

struct CadPart {
  std::string name;
  std::vector<CadFace> faces;
  std::vector<std::string> datums;  // "A on #123"
  // The part's shape as triangles for a viewer (BRepMesh, kMeshDeflection): 9 numbers a
  // triangle, its corners' x y z, m, in the assembly's frame, counter-clockwise seen from outside.
  // Empty with `mesh_note` saying why when the shape gives more than kMaxMeshTriangles.
  std::vector<float> mesh;
  std::string mesh_note;
};

// Fine enough that a 20 mm part's drawn outline stays within a twentieth of a millimetre of its
// surface; the angular bound keeps small radii round.
inline constexpr double kMeshLinearDeflection = 0.05e-3;  // m
inline constexpr double kMeshAngularDeflection = 0.5;     // rad
// Bounds what crosses the pipe and the page's first message (about 90 bytes a triangle as text).
inline constexpr std::size_t kMaxMeshTriangles = 100000;

struct CadDocument {
  std::string schema;       // the file's FILE_SCHEMA, as the reader reports it
  std::string length_unit;  // the file's length unit, e.g. "MM", "INCH"
  std::vector<CadPart> parts;
  std::vector<CadTolerance> tolerances;
};

// The text form sent through the pipe (JSON), and back. FromText throws std::runtime_error on a
// text that is not such a document.
std::string ToText(const CadDocument& document);
CadDocument FromText(const std::string& text);

}  // namespace fitfeel::cad
