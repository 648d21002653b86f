// The CAD import's library: the fixtures read through the child process, every refusal with its
// message, feature grouping and pairing, the sidecar.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/cad/import.h"
#include "framework/cad/isolated_read.h"
#include "framework/core/error.h"
#include "framework/scenario/cad_parts.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel::cad {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path Fixture(const std::string& name) {
  return fs::path(fitfeel_test_build_dir()) / "cad-fixtures" / name;
}
fs::path Sidecar(const std::string& name) {
  return fs::path(fitfeel_test_source_dir()) / "framework/cad/test" / name;
}

// The message of the UserError `action` throws; fails the test when it throws none.
template <typename F>
std::string Refusal(F action) {
  try {
    action();
  } catch (const UserError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UserError";
  return "";
}

const Feature& Named(const Import& import, const std::string& part, const std::string& name) {
  for (const Feature& f : import.features) {
    if (f.part == part && f.name == name) return f;
  }
  throw std::runtime_error("no feature " + part + " " + name);
}

TEST(CadImport, Ap242GivesPartsFeaturesTolerancesAndOnePair) {
  const Import import = BuildImport(ReadStep(Fixture("paper-ap242.step")), std::nullopt);
  ASSERT_EQ(import.document.parts.size(), 2u);
  EXPECT_EQ(import.document.parts[0].name, "bushing");
  EXPECT_EQ(import.document.parts[1].name, "shaft");
  const Feature& bore = Named(import, "bushing", "hole-1");
  EXPECT_NEAR(bore.diameter, 0.020, 1e-12);
  EXPECT_NEAR(bore.axial_max - bore.axial_min, 0.020, 1e-12);
  const Feature& outside = Named(import, "bushing", "cylinder-1");
  EXPECT_NEAR(outside.diameter, 0.030, 1e-12);
  const Feature& journal = Named(import, "shaft", "cylinder-1");
  EXPECT_NEAR(journal.axial_max - journal.axial_min, 0.040, 1e-12);
  ASSERT_EQ(import.pairs.size(), 1u);
  const std::string listing = DescribeImport(import);
  EXPECT_THAT(listing, HasSubstr("size 20 mm H7 (0 um / 21 um, from STEP #"));
  EXPECT_THAT(listing, HasSubstr("size 20 mm g6 (-20 um / -7 um, from STEP #"));
  EXPECT_THAT(listing, HasSubstr("roundness 10 um (from STEP #"));
  EXPECT_THAT(listing, HasSubstr("straightness 10 um (from STEP #"));
  EXPECT_THAT(listing, HasSubstr("pair 1: bushing hole-1 / shaft cylinder-1 (Ø20 mm, coaxial)"));
}

TEST(CadImport, ABoreSplitIntoTwoHalvesIsOneHole) {
  const Import import = BuildImport(ReadStep(Fixture("paper-split-bore-ap242.step")), std::nullopt);
  const Feature& bore = Named(import, "bushing", "hole-1");
  EXPECT_EQ(bore.faces.size(), 2u);
  EXPECT_NEAR(bore.axial_max - bore.axial_min, 0.020, 1e-12);
  EXPECT_EQ(Named(import, "bushing", "cylinder-1").faces.size(), 2u);
  EXPECT_EQ(import.pairs.size(), 1u);
}

TEST(CadImport, ATaperPinAndItsReamedHoleAreAConicalPair) {
  const Import import = BuildImport(ReadStep(Fixture("taper-pin-ap242.step")), std::nullopt);
  const Feature& pin = Named(import, "pin", "cone-1");
  EXPECT_NEAR(pin.diameter, 0.008, 1e-12);
  EXPECT_NEAR(pin.large_diameter, 0.0088, 1e-12);
  EXPECT_NEAR(pin.axial_max - pin.axial_min, 0.040, 1e-12);
  const Feature& hole = Named(import, "hub", "taper-hole-1");
  EXPECT_NEAR(hole.diameter, 0.008, 1e-12);
  EXPECT_NEAR(hole.large_diameter, 0.0084, 1e-12);
  EXPECT_NEAR(std::abs(hole.slope), 0.01, 1e-12);
  ASSERT_EQ(import.pairs.size(), 1u);
  EXPECT_THAT(DescribeImport(import),
              HasSubstr("pair 1: hub taper-hole-1 / pin cone-1 (Ø8 mm at the small end, taper "
                        "\"1:50\", coaxial)"));
  const std::string text = ScenarioText(import, "taper", "taper-pin-ap242.step");
  EXPECT_THAT(text, HasSubstr("surface: fitfeel.surface.conical"));
  EXPECT_THAT(text, HasSubstr("size: 8 mm h10"));
  EXPECT_THAT(text, HasSubstr("geometry: {length: 40 mm, taper: \"1:50\"}"));
  EXPECT_THAT(text, HasSubstr("geometry: {length: 20 mm, taper: \"1:50\", outer_diameter: 24 mm}"));
}

TEST(CadImport, ABallInItsSeatIsASphericalPair) {
  const Import import = BuildImport(ReadStep(Fixture("knuckle-bearing-ap242.step")), std::nullopt);
  const Feature& ball = Named(import, "inner_ring", "sphere-1");
  EXPECT_NEAR(ball.diameter, 0.029, 1e-12);
  EXPECT_NEAR(ball.axial_max - ball.axial_min, 0.016, 1e-12);
  EXPECT_NEAR(Named(import, "outer_ring", "seat-1").axial_max -
                  Named(import, "outer_ring", "seat-1").axial_min,
              0.012, 1e-12);
  ASSERT_EQ(import.pairs.size(), 1u);
  const std::string text = ScenarioText(import, "knuckle", "knuckle-bearing-ap242.step");
  EXPECT_THAT(text, HasSubstr("surface: fitfeel.surface.spherical"));
  EXPECT_THAT(text, HasSubstr("geometry: {width: 16 mm, bore_diameter: 20 mm}"));
  EXPECT_THAT(text, HasSubstr("geometry: {width: 12 mm, outer_diameter: 35 mm}"));
  EXPECT_THAT(text, HasSubstr("mode: constant_rotation"));
}

TEST(CadImport, TwoPinsUnderAPlateAreOneSceneOfTwoFeatures) {
  const Import bare = BuildImport(ReadStep(Fixture("two-pin-ap242.step")), std::nullopt);
  ASSERT_EQ(bare.pairs.size(), 2u);
  EXPECT_THAT(DescribeImport(bare), HasSubstr("scene: the 2 pairs as the features of one joint"));
  EXPECT_THAT(Refusal([&] { ScenarioText(bare, "x", "two-pin-ap242.step"); }),
              HasSubstr("part plate has no outer cylinder on the axis of hole-1"));
  const Import import =
      BuildImport(ReadStep(Fixture("two-pin-ap242.step")), Sidecar("two-pin.sidecar.yaml"));
  const std::string text = ScenarioText(import, "two-pin", "two-pin-ap242.step");
  EXPECT_THAT(text, HasSubstr("features:\n  hole-1:"));
  EXPECT_THAT(text, HasSubstr("  hole-2:   # plate hole-2 / base cylinder-2"));
  EXPECT_THAT(text, HasSubstr("at: {x: 60 mm, z: 0 mm}"));
  EXPECT_THAT(text, HasSubstr("position: {base: 40 um, plate: 40 um}"));
  // Either pair alone is still a scene of its own.
  EXPECT_THAT(ScenarioText(import, "pin-b", "two-pin-ap242.step", 1),
              HasSubstr("surface: fitfeel.surface.cylindrical\nparts:\n  base:"));
}

// A cylindrical face as the reader gives it: axis along z through (x, 0), extent z0 to z1 (m).
CadFace Cylinder(int entity, double x, double radius, double z0, double z1, bool convex) {
  CadFace face;
  face.entity = entity;
  face.kind = SurfaceKind::kCylinder;
  face.origin = {x, 0.0, 0.0};
  face.axis = {0.0, 0.0, 1.0};
  face.radius = radius;
  face.axial_min = z0;
  face.axial_max = z1;
  face.convex = convex;
  return face;
}

TEST(CadImport, TheFirstPinToEngageIsTheDatumAndTheOtherEngagesAfterIt) {
  // Pin B (x = 60 mm) stands 15 mm above the base, pin A 2 mm less; the plate's holes start at
  // z = 15 mm, so pin B meets its hole first.
  CadDocument document;
  document.schema = "synthetic";
  document.length_unit = "MM";
  document.parts.push_back(
      {"base",
       {Cylinder(1, 0.0, 0.004, 0.0, 0.013, true), Cylinder(2, 0.060, 0.004, 0.0, 0.015, true)},
       {},
       {},
       {}});
  document.parts.push_back({"plate",
                            {Cylinder(3, 0.0, 0.004, 0.015, 0.025, false),
                             Cylinder(4, 0.060, 0.004, 0.015, 0.025, false)},
                            {},
                            {},
                            {}});
  const fs::path sidecar = test_support::EmptyTestFolder("cad-joint") / "joint.sidecar.yaml";
  std::ofstream(sidecar)
      << "parts:\n"
         "  base:\n"
         "    features:\n"
         "      cylinder-1: {size: 8 mm m6}\n"
         "      cylinder-2: {size: 8 mm m6}\n"
         "  plate:\n"
         "    features:\n"
         "      hole-1: {size: 8 mm E7, outer_diameter: 24 mm, position: 20 um}\n"
         "      hole-2: {size: 8 mm E7, outer_diameter: 24 mm}\n";
  const Import import = BuildImport(document, sidecar);
  ASSERT_EQ(import.pairs.size(), 2u);
  const std::string text = ScenarioText(import, "joint", "synthetic");
  EXPECT_THAT(text, HasSubstr("features:\n  hole-2:   # plate hole-2 / base cylinder-2 (Ø8 mm, "
                              "coaxial), the datum: the first to engage\n"));
  EXPECT_THAT(text, HasSubstr("  hole-1:   # plate hole-1 / base cylinder-1"));
  EXPECT_THAT(text, HasSubstr("at: {x: 60 mm, z: 0 mm}"));
  EXPECT_THAT(text, HasSubstr("engages_after: 2 mm"));
  EXPECT_THAT(text, HasSubstr("position: {plate: 20 um}"));
  // A position tolerance on the datum is refused: it places the others.
  std::ofstream(sidecar) << "parts:\n"
                            "  base:\n"
                            "    features:\n"
                            "      cylinder-1: {size: 8 mm m6}\n"
                            "      cylinder-2: {size: 8 mm m6, position: 20 um}\n"
                            "  plate:\n"
                            "    features:\n"
                            "      hole-1: {size: 8 mm E7, outer_diameter: 24 mm}\n"
                            "      hole-2: {size: 8 mm E7, outer_diameter: 24 mm}\n";
  const Import datum = BuildImport(document, sidecar);
  EXPECT_THAT(Refusal([&] { ScenarioText(datum, "joint", "synthetic"); }),
              HasSubstr("the sidecar gives a position tolerance to base's cylinder-2, of the "
                        "datum feature"));
}

TEST(CadImport, PairsOfDifferentPartsAreWrittenOnePerPair) {
  const Import import = BuildImport(ReadStep(Fixture("separate-pins-ap242.step")),
                                    Sidecar("separate-pins.sidecar.yaml"));
  ASSERT_EQ(import.pairs.size(), 2u);
  EXPECT_THAT(DescribeImport(import),
              HasSubstr("scene: one per pair, with --pair N: the pairs form no joint (they join "
                        "different parts"));
  EXPECT_THAT(Refusal([&] { ScenarioText(import, "x", "separate-pins-ap242.step"); }),
              HasSubstr("write one scenario per pair with --pair N"));
  const std::string second = ScenarioText(import, "x", "separate-pins-ap242.step", 1);
  EXPECT_THAT(second, HasSubstr("  pin-2:\n    role: inner"));
  EXPECT_THAT(second, HasSubstr("outer_diameter: 24 mm"));
  EXPECT_THAT(Refusal([&] { ScenarioText(import, "x", "separate-pins-ap242.step", 2); }),
              HasSubstr("--pair 3 names no pair: there are 2"));
}

TEST(CadImport, Ap214WithoutPmiNeedsTheSidecar) {
  const Import bare = BuildImport(ReadStep(Fixture("paper-ap214.step")), std::nullopt);
  EXPECT_TRUE(bare.tolerances.empty());
  EXPECT_THAT(Refusal([&] { ScenarioText(bare, "x", "paper-ap214.step"); }),
              HasSubstr("has no size tolerance in the STEP file; give it in the sidecar"));
  const Import with =
      BuildImport(ReadStep(Fixture("paper-ap214.step")), Sidecar("paper-ap214.sidecar.yaml"));
  EXPECT_THAT(DescribeImport(with), HasSubstr("size 20 mm g6 (-20 um / -7 um, from sidecar)"));
}

TEST(CadImport, EveryUntrustedPmiValueIsRefusedNamingItsFace) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"zero-tolerance-ap242.step",
       "diameter on face #240 is refused: both deviations read as 0 (the reader gives 0 for a "
       "value it did not read); give it in the sidecar instead"},
      // OCCT 7.6 reads its own ± output back as a range about a wrong nominal.
      {"plus-minus-ap242.step",
       "diameter on face #240 is refused: its nominal 10.01 mm is not the face's diameter 20 mm "
       "(a value not in the document's unit)"},
      {"inverted-tolerance-ap242.step", "diameter on face #240 is refused: its nominal"},
      {"undefined-class-ap242.step", "diameter on face #192 is refused: its ISO 286 class K9"},
      {"inch-plus-minus-ap242.step",
       "diameter on face #195 is refused: its nominal 508 mm is not the face's diameter 20 mm"},
      {"bspline-bore-ap242.step",
       "diameter on face #255 is refused: the face is a B-spline surface"},
  };
  for (const auto& [file, says] : cases) {
    EXPECT_THAT(Refusal([&] { BuildImport(ReadStep(Fixture(file)), std::nullopt); }),
                HasSubstr(says))
        << file;
  }
}

// Values OCCT's writer cannot be made to produce, checked on the reader's output directly.
TEST(CadImport, InvertedDeviationsAndInchValuesAreRefused) {
  CadDocument document = ReadStep(Fixture("paper-ap242.step"));
  CadDocument inverted = document;
  for (CadTolerance& t : inverted.tolerances) {
    if (t.kind == ToleranceKind::kSize && t.iso_class == "g6") {
      t.iso_class.clear();
      t.has_plus_minus = true;
      t.lower = 7e-6;  // the sign of -7 um dropped
      t.upper = -20e-6;
    }
  }
  EXPECT_THAT(Refusal([&] { BuildImport(inverted, std::nullopt); }),
              HasSubstr("its lower deviation 7 um is not below its upper -20 um (the reader may "
                        "drop a lower deviation's sign)"));
  CadDocument inch = document;
  inch.length_unit = "INCH";
  EXPECT_THAT(Refusal([&] { BuildImport(inch, std::nullopt); }),
              HasSubstr("tolerance on face #192 is refused: the file's length unit is INCH"));
}

TEST(CadImport, ABSplineFaceOnAMatingCylinderIsRefused) {
  CadDocument document = ReadStep(Fixture("bspline-bore-ap242.step"));
  document.tolerances.clear();
  EXPECT_THAT(Refusal([&] { BuildImport(document, std::nullopt); }),
              HasSubstr("part bushing: face #255 is a B-spline surface where it mates with shaft's "
                        "cylinder-1 (Ø20 mm)"));
}

TEST(CadImport, ASidecarValueThatDisagreesWithTheStepFileIsAnError) {
  const std::string message = Refusal([&] {
    BuildImport(ReadStep(Fixture("paper-ap242.step")), Sidecar("disagreeing.sidecar.yaml"));
  });
  EXPECT_THAT(message, HasSubstr("disagreeing.sidecar.yaml:5:"));
  EXPECT_THAT(message, HasSubstr("expected the value the STEP file gives (STEP #240: g6, -20 um / "
                                 "-7 um) or none, found '20 mm h6'"));
}

TEST(CadImport, FilesThatAreNoStepTextAreRefusedBeforeReading) {
  const fs::path dir = test_support::EmptyTestFolder("cad");
  const std::string good = test_support::ReadText(Fixture("paper-ap242.step"));
  test_support::WriteText(dir / "empty.step", "");
  test_support::WriteText(dir / "truncated.step", good.substr(0, good.size() / 2));
  test_support::WriteText(dir / "binary.step", std::string("\x7f"
                                                           "ELF\x02\x01\x01\0\0",
                                                           9) +
                                                   good);
  test_support::WriteText(dir / "big.step", good);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty.step", "is empty"},
      {"truncated.step", "is truncated: it does not end with END-ISO-10303-21;"},
      {"binary.step", "is not a STEP file: it holds binary bytes"},
  };
  for (const auto& [file, says] : cases) {
    EXPECT_THAT(Refusal([&] { ReadStep(dir / file); }), HasSubstr(says)) << file;
  }
  ReadLimits small;
  small.max_bytes = 1000;
  EXPECT_THAT(Refusal([&] { ReadStep(dir / "big.step", small); }),
              HasSubstr("bytes, above the 1000 bytes the import reads"));
  // The real cap, on a sparse file of 513 MiB that holds no data.
  { std::ofstream sparse(dir / "huge.step"); }
  ASSERT_EQ(::truncate((dir / "huge.step").c_str(), off_t{513} << 20), 0);
  EXPECT_THAT(Refusal([&] { ReadStep(dir / "huge.step"); }),
              HasSubstr("is 537919488 bytes, above the 536870912 bytes the import reads"));
}

TEST(CadImport, AReaderThatCrashesOrHangsEndsInARefusal) {
  ::setenv("FITFEEL_TEST_CAD_READER", "abort", 1);
  const std::string crashed = Refusal([] { ReadStep(Fixture("paper-ap242.step")); });
  ::setenv("FITFEEL_TEST_CAD_READER", "hang", 1);
  ReadLimits quick;
  quick.seconds = 0.3;
  const std::string hung = Refusal([&] { ReadStep(Fixture("paper-ap242.step"), quick); });
  ::unsetenv("FITFEEL_TEST_CAD_READER");
  EXPECT_THAT(crashed, HasSubstr("crashed the STEP reader (Aborted); the reader ran in a child "
                                 "process and the file is refused"));
  EXPECT_THAT(hung, HasSubstr("was not read within 0.3 s; the STEP reader was stopped"));
}

}  // namespace
}  // namespace fitfeel::cad

namespace fitfeel::cad {
namespace {

// The viewer's triangles of the paper case's parts: their area and enclosed volume (the
// divergence theorem, which also checks that every triangle faces out) within 2 % of the
// cylinders' own, their extent the parts' within the mesher's deflection.
TEST(CadImport, EachPartsTessellationHasItsAreaVolumeAndExtent) {
  const CadDocument document = ReadStep(Fixture("paper-ap242.step"));
  struct Expected {
    const char* name;
    double area, volume, dx, dz;  // mm², mm³, mm across, mm along
  };
  const double pi = std::acos(-1.0);
  for (const Expected& e : {Expected{"shaft", 1000 * pi, 4000 * pi, 20, 40},
                            Expected{"bushing", 1250 * pi, 2500 * pi, 30, 20}}) {
    SCOPED_TRACE(e.name);
    const CadPart* part = nullptr;
    for (const CadPart& p : document.parts) {
      if (p.name == e.name) part = &p;
    }
    ASSERT_NE(part, nullptr);
    ASSERT_FALSE(part->mesh.empty()) << part->mesh_note;
    ASSERT_EQ(part->mesh.size() % 9, 0u);
    double area = 0.0, volume = 0.0;
    std::array<double, 3> lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
    for (std::size_t t = 0; t < part->mesh.size(); t += 9) {
      std::array<std::array<double, 3>, 3> c;
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) {
          c[k][a] = part->mesh[t + 3 * k + a] * 1e3;
          lo[a] = std::min(lo[a], c[k][a]);
          hi[a] = std::max(hi[a], c[k][a]);
        }
      }
      const std::array<double, 3> u{c[1][0] - c[0][0], c[1][1] - c[0][1], c[1][2] - c[0][2]};
      const std::array<double, 3> v{c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]};
      const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                    u[0] * v[1] - u[1] * v[0]};
      area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      volume += (c[0][0] * n[0] + c[0][1] * n[1] + c[0][2] * n[2]) / 6.0;
    }
    EXPECT_NEAR(area, e.area, 0.02 * e.area);
    EXPECT_NEAR(volume, e.volume, 0.02 * e.volume);
    const double deflection = kMeshLinearDeflection * 1e3;
    EXPECT_NEAR(hi[0] - lo[0], e.dx, 2 * deflection);
    EXPECT_NEAR(hi[1] - lo[1], e.dx, 2 * deflection);
    EXPECT_NEAR(hi[2] - lo[2], e.dz, 1e-6);
  }
}

}  // namespace
}  // namespace fitfeel::cad

namespace fitfeel::cad {
namespace {

// A scene's parts made of the paper case's features carry the parts' own shapes in their mating
// frames (framework/model/render_mesh.h): the shaft's leading end at y = 0 and its body behind
// it, the bushing entered at y = 0 and lying beyond, both about the y axis.
TEST(CadImport, AScenesCadPartsCarryTheirShapesInTheirMatingFrames) {
  const fs::path dir = test_support::EmptyTestFolder("cad-part-meshes");
  fs::copy_file(Fixture("paper-ap242.step"), dir / "paper-ap242.step");
  const std::string sidecar = Sidecar("paper-ap242.sidecar.yaml").string();
  std::ofstream(dir / "cad.yaml")
      << "scenario: cad-meshes\nsurface: fitfeel.surface.cylindrical\nparts:\n"
      << "  shaft: {role: inner, cad: {file: paper-ap242.step, feature: cylinder-1, sidecar: \""
      << sidecar << "\"}}\n"
      << "  bushing: {role: outer, cad: {file: paper-ap242.step, feature: hole-1, sidecar: \""
      << sidecar << "\"}}\n"
      << "moving: shaft\n"
         "model: {law: elastic, friction: 0.15, contact_stiffness: 3665 N/um, resolution: "
         "{rows: 40, columns: 360}, texture: din7190, options: {tilt: free}, depth_step: auto}\n"
         "device: {plugin: fitfeel.device.simulated, speed: 10 mm/s}\n"
         "run: {rate: 1000 Hz, duration: 4 s, seed: 1, clock: virtual}\n";
  InstallSceneCadParts();
  const Scene scene = LoadScene(dir / "cad.yaml", test_support::BuildTreePlugins());
  scenario::SetCadPartResolver({});
  struct Expected {
    const char* name;
    double radius, y_min, y_max;  // mm
  };
  for (const Expected& e : {Expected{"shaft", 10, -40, 0}, Expected{"bushing", 15, 0, 20}}) {
    SCOPED_TRACE(e.name);
    const std::shared_ptr<const scenario::CadMesh> mesh = scenario::CadMeshOf(scene.file, e.name);
    ASSERT_NE(mesh, nullptr);
    ASSERT_FALSE(mesh->triangles.empty()) << mesh->note;
    double y_min = 1e9, y_max = -1e9, radius = 0.0;
    for (std::size_t i = 0; i < mesh->triangles.size(); i += 3) {
      const double x = mesh->triangles[i] * 1e3, y = mesh->triangles[i + 1] * 1e3,
                   z = mesh->triangles[i + 2] * 1e3;
      y_min = std::min(y_min, y);
      y_max = std::max(y_max, y);
      radius = std::max(radius, std::hypot(x, z));
    }
    EXPECT_NEAR(y_min, e.y_min, 1e-3);
    EXPECT_NEAR(y_max, e.y_max, 1e-3);
    EXPECT_NEAR(radius, e.radius, 1e-3);
  }
}

}  // namespace
}  // namespace fitfeel::cad
