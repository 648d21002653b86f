#pragma once

// The conformance suite every surface plugin instantiates, header-only. A plugin's test folder
// holds a small scenario of its surface type and one line:
//
//   FITFEEL_SURFACE_CONFORMANCE(Cylindrical, "surfaces/cylindrical/test/conformance.yaml");
//
// or, where the scene needs plugins from a folder the registry does not search by itself (a test
// device, a plugin built outside the plugin folder), that folder as a third argument:
//
//   FITFEEL_SURFACE_CONFORMANCE_WITH_PLUGINS(Conical, "surfaces/conical/test/conformance.yaml",
//                                            std::string(FITFEEL_TEST_BUILD_DIR) +
//                                                "/test-plugins/good");
//
// The scenario is loaded through the plugin registry, so the suite also proves the plugin
// registers and validates like any other. Paths are relative to the repository root (ctest runs
// tests there). A surface type without a resistance law (renders_forces() == false) gets the
// geometric tests and skips the force tests with a message saying why.
//
// EvaluateNeverAllocates counts operator new: the binary must replace it once
// (FITFEEL_COUNT_ALLOCATIONS, framework/testing/allocation_counter.h), or that test fails saying
// so. In this tree every plugin's suite is linked into fitfeel_allocation_test, which does.

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/prepare.h"
#include "framework/scenario/scene.h"
#include "framework/testing/allocation_counter.h"

namespace fitfeel::conformance {

// How many seeds the property tests draw; plugins with slow generators may pass fewer.
inline constexpr int kDefaultSeeds = 60;

template <typename Traits>
class SurfaceConformance : public ::testing::Test {
 protected:
  void SetUp() override {
    // The search path of this suite's own registry: several suites share a binary, so none
    // changes the process's FITFEEL_PLUGIN_PATH.
    std::vector<std::filesystem::path> search_path = PluginRegistry::DefaultSearchPath();
    const std::string folder = Traits::PluginFolder();
    if (!folder.empty()) search_path.insert(search_path.begin(), folder);
    registry_ = std::make_unique<PluginRegistry>(search_path);
    registry_->LoadAll();
    LoadOptions options;
    options.allow_non_rendering = true;
    scene_ = LoadScene(Traits::kScenario, *registry_, options);
  }

  const PartSpec& part(int k) const { return k == 0 ? scene_.inner : scene_.outer; }

  SkinModelShape Generate(const PartSpec& p, std::uint64_t seed) const {
    const auto discretizer = scene_.surface->MakeDiscretizer();
    const auto generator = scene_.surface->MakeVariationGenerator();
    const SurfaceGrid grid = discretizer->Discretize(p, scene_.model.resolution);
    Rng rng(seed);
    return generator->Generate(p, grid, scene_.model.texture, rng);
  }

  // Prepares analyzer and law for the scene's parts at `seed`; null law if the surface renders no
  // forces.
  void PrepareModel(std::uint64_t seed, std::unique_ptr<ContactAnalyzer>* analyzer,
                    std::unique_ptr<ResistanceLaw>* law) const {
    Rng rng(seed);
    const SkinModelShapes shapes = GenerateSkinModelShapes(scene_, rng);
    const SkinModelShape& inner = shapes.inner;
    const SkinModelShape& outer = shapes.outer;
    *analyzer = scene_.surface->MakeContactAnalyzer();
    (*analyzer)->Prepare(scene_.inner, inner, scene_.outer, outer, scene_.model);
    *law = scene_.surface->MakeLaw(scene_.model.law);
    (*law)->Prepare(scene_.inner, scene_.outer, scene_.model);
  }

  // A radial offset 50 um past the largest interference (or the widest clearance) the scene's
  // tolerances allow: a sweep from the axis to it must meet the mating part.
  double RadialReach() const {
    return std::abs(scene_.inner.size.upper_deviation - scene_.outer.size.lower_deviation) + 50e-6;
  }

  // Largest change of the force magnitude between neighbouring samples of a sweep of `samples`
  // poses from `from` to `to`, and the largest magnitude on the way.
  struct Sweep {
    double largest_jump = 0.0;
    double peak = 0.0;
  };
  static Sweep SweepForce(const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                          const MatingPose& from, const MatingPose& to, int samples) {
    MatingMotion motion;
    motion.velocity.y() = 0.01;
    ContactState contact;
    Wrench wrench;
    double previous = 0.0;
    Sweep sweep;
    for (int k = 0; k <= samples; ++k) {
      const double s = static_cast<double>(k) / samples;
      MatingPose pose;
      pose.depth = from.depth + s * (to.depth - from.depth);
      pose.offset = from.offset + s * (to.offset - from.offset);
      pose.angle = from.angle + s * (to.angle - from.angle);
      analyzer.Evaluate(pose, &contact);
      law.Evaluate(contact, motion, &wrench);
      const double magnitude = wrench.force.norm() + wrench.torque.norm();
      if (k > 0) sweep.largest_jump = std::max(sweep.largest_jump, std::abs(magnitude - previous));
      sweep.peak = std::max(sweep.peak, magnitude);
      previous = magnitude;
    }
    return sweep;
  }

  std::unique_ptr<PluginRegistry> registry_;
  Scene scene_;
};

TYPED_TEST_SUITE_P(SurfaceConformance);

TYPED_TEST_P(SurfaceConformance, CellAreasSumToTheNominalArea) {
  for (int k = 0; k < 2; ++k) {
    const PartSpec& p = this->part(k);
    const SurfaceGrid grid =
        this->scene_.surface->MakeDiscretizer()->Discretize(p, this->scene_.model.resolution);
    ASSERT_GT(grid.size(), 0);
    EXPECT_NEAR(grid.area.sum(), p.geometry->nominal_area(), 1e-9 * p.geometry->nominal_area())
        << p.name;
    EXPECT_TRUE((grid.area.array() > 0.0).all()) << p.name;
  }
}

TYPED_TEST_P(SurfaceConformance, ZeroTolerancesGiveZeroVariation) {
  for (int k = 0; k < 2; ++k) {
    PartSpec p = this->part(k);
    p.size.lower_deviation = 0.0;
    p.size.upper_deviation = 0.0;
    for (auto& [characteristic, tolerance] : p.form.tolerance) tolerance = 0.0;
    for (auto& [name, tolerance] : p.form.declared) tolerance = 0.0;
    p.texture = TextureSpec{};
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const SkinModelShape sms = this->Generate(p, seed);
      EXPECT_EQ(sms.variation.cwiseAbs().maxCoeff(), 0.0) << p.name << " seed " << seed;
    }
  }
}

TYPED_TEST_P(SurfaceConformance, EverySkinModelShapeMeetsItsTolerances) {
  // 0.1 nm: far below any tolerance, above the rounding of evaluation in double precision.
  constexpr double kSlack = 1e-10;
  for (int k = 0; k < 2; ++k) {
    const PartSpec& p = this->part(k);
    for (int seed = 1; seed <= TypeParam::kSeeds; ++seed) {
      const SkinModelShape sms = this->Generate(p, seed);
      const auto checks = this->scene_.surface->EvaluateCharacteristics(p, sms);
      ASSERT_FALSE(checks.empty()) << p.name;
      for (const auto& check : checks) {
        EXPECT_GE(check.value, check.lower - kSlack)
            << p.name << " seed " << seed << ": " << check.name;
        EXPECT_LE(check.value, check.upper + kSlack)
            << p.name << " seed " << seed << ": " << check.name;
      }
    }
  }
}

TYPED_TEST_P(SurfaceConformance, SameSeedGivesTheSameShape) {
  for (int k = 0; k < 2; ++k) {
    const PartSpec& p = this->part(k);
    const SkinModelShape a = this->Generate(p, 7);
    const SkinModelShape b = this->Generate(p, 7);
    const SkinModelShape c = this->Generate(p, 8);
    ASSERT_EQ(a.variation.size(), b.variation.size());
    EXPECT_TRUE((a.variation.array() == b.variation.array()).all()) << p.name;
    if (a.variation.cwiseAbs().maxCoeff() > 0.0) {
      EXPECT_FALSE((a.variation.array() == c.variation.array()).all()) << p.name;
    }
  }
}

TYPED_TEST_P(SurfaceConformance, ForceIsContinuousAcrossContactOnset) {
  if (!this->scene_.surface->renders_forces()) {
    GTEST_SKIP() << "no resistance law: " << this->scene_.surface->limitation();
  }
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
  this->PrepareModel(11, &analyzer, &law);
  const double length = this->scene_.inner.geometry->mating_length();
  const double reach = this->RadialReach();
  // Radially from the axis to well past first contact at mid engagement, and axially on the axis
  // through the entrance, where the overlap starts. A continuous force has jumps that halve with
  // the step; a step in the force keeps its jump whatever the step. The radial sweep ends 50 um
  // past the largest interference the tolerances allow, so it must meet a force: a law that
  // renders nothing would otherwise pass.
  MatingPose radial_from, radial_to, axial_from, axial_to;
  radial_from.depth = radial_to.depth = 0.5 * length;
  radial_to.offset = Eigen::Vector2d(0.6, -0.8) * reach;
  axial_from.depth = -0.05 * length;
  axial_to.depth = 0.3 * length;
  bool radial = true;
  for (const auto& [from, to] : {std::pair{radial_from, radial_to}, std::pair{axial_from, axial_to}}) {
    const auto coarse = this->SweepForce(*analyzer, *law, from, to, 2000);
    const auto fine = this->SweepForce(*analyzer, *law, from, to, 8000);
    if (radial) {
      ASSERT_GT(fine.peak, 0.0) << "no force pushing the part 50 um past the largest "
                                   "interference: continuity would be untested";
      radial = false;
    }
    EXPECT_LE(fine.largest_jump, 0.5 * coarse.largest_jump + 1e-9)
        << "a force step that does not shrink with the sample step";
  }
}

TYPED_TEST_P(SurfaceConformance, EvaluateNeverAllocates) {
  if (!this->scene_.surface->renders_forces()) {
    GTEST_SKIP() << "no resistance law: " << this->scene_.surface->limitation();
  }
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
  this->PrepareModel(5, &analyzer, &law);
  const double length = this->scene_.inner.geometry->mating_length();
  ContactState contact;
  Wrench wrench;
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  // Fed by the operator new that FITFEEL_SURFACE_CONFORMANCE replaces.
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  for (int k = 0; k < 1000; ++k) {
    MatingPose pose;
    pose.depth = (k / 1000.0) * length;
    pose.offset = Eigen::Vector2d(1e-6 * std::sin(k), -1e-6 * std::cos(k));
    analyzer->Evaluate(pose, &contact);
    law->Evaluate(contact, motion, &wrench);
  }
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_TRUE(wrench.AllFinite());
}

// The assembly space (paper 3.1) bounds where the moving axis may go without contact: a point
// just beyond any vertex of the polygon touches. (That points inside touch nothing is each
// plugin's own test, at depths where its tables are exact.) A surface type that does not describe
// its assembly space skips, saying so.
TYPED_TEST_P(SurfaceConformance, ContactBeyondTheAssemblySpace) {
  if (!this->scene_.surface->renders_forces()) {
    GTEST_SKIP() << "no resistance law: " << this->scene_.surface->limitation();
  }
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
  this->PrepareModel(3, &analyzer, &law);
  const double length = this->scene_.inner.geometry->mating_length();
  int polygons = 0;
  for (const double fraction : {0.3, 0.6, 0.9}) {
    MatingPose pose;
    pose.depth = fraction * length;
    std::vector<Eigen::Vector2d> polygon;
    if (!analyzer->AssemblySpace(pose, &polygon)) {
      GTEST_SKIP() << "this surface type does not describe its assembly space";
    }
    if (polygon.empty()) continue;
    ++polygons;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& v : polygon) centre += v / static_cast<double>(polygon.size());
    for (const auto& v : polygon) {
      MatingPose beyond = pose;
      beyond.offset = centre + 1.1 * (v - centre);
      ContactState contact;
      analyzer->Evaluate(beyond, &contact);
      EXPECT_TRUE(contact.penetration > 0.0 || contact.interference_volume > 0.0)
          << "depth " << pose.depth << ", beyond " << v.transpose();
    }
  }
  EXPECT_GT(polygons, 0) << "no depth with a non-empty assembly space: nothing was checked";
}

// A law that gives its radial stiffness in closed form (ResistanceLaw::RadialJacobian; the
// settling and the god object step on it instead of differences) gives the derivative of the
// radial force it renders: against central differences over 1 pm at poses from the axis to 50 um
// past the largest interference at mid engagement, where the Jacobian is the same either side of
// the difference (no piece of the contact changes within it). A surface type whose law gives none
// skips, saying so.
TYPED_TEST_P(SurfaceConformance, ARadialJacobianIsTheRadialForcesDerivative) {
  if (!this->scene_.surface->renders_forces()) {
    GTEST_SKIP() << "no resistance law: " << this->scene_.surface->limitation();
  }
  std::unique_ptr<ContactAnalyzer> analyzer;
  std::unique_ptr<ResistanceLaw> law;
  this->PrepareModel(7, &analyzer, &law);
  const double length = this->scene_.inner.geometry->mating_length();
  const double reach = this->RadialReach();
  auto radial = [&](const MatingPose& pose, ContactState* contact) {
    analyzer->Evaluate(pose, contact);
    Wrench w;
    law->Evaluate(*contact, MatingMotion{}, &w);
    return Eigen::Vector2d(w.force.x(), w.force.z());
  };
  int given = 0, compared = 0;
  for (int k = 0; k < 400; ++k) {
    MatingPose pose;
    pose.depth = (0.4 + 0.2 * std::sin(0.37 * k) * std::sin(0.37 * k)) * length;
    const double angle = 2.399963 * k;  // the golden angle: directions all round
    pose.offset = (reach * (k + 0.5) / 400.0) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    ContactState contact;
    radial(pose, &contact);
    Eigen::Matrix2d jacobian;
    if (!law->RadialJacobian(contact, &jacobian)) continue;
    ++given;
    constexpr double h = 1e-12;
    Eigen::Matrix2d numeric;
    bool smooth = true;
    for (int axis = 0; axis < 2; ++axis) {
      MatingPose plus = pose, minus = pose;
      plus.offset[axis] += h;
      minus.offset[axis] -= h;
      ContactState a, b;
      numeric.col(axis) = (radial(plus, &a) - radial(minus, &b)) / (2.0 * h);
      Eigen::Matrix2d ja, jb;
      smooth = smooth && law->RadialJacobian(a, &ja) && law->RadialJacobian(b, &jb) &&
               ja.isApprox(jb, 1e-12);
    }
    if (!smooth) continue;
    ++compared;
    EXPECT_LT((numeric - jacobian).norm(), 1e-5 * jacobian.norm())
        << "depth " << pose.depth << ", offset " << pose.offset.transpose();
  }
  if (given == 0) {
    GTEST_SKIP() << "this surface type's law gives no radial stiffness in closed form";
  }
  EXPECT_GT(compared, given / 4) << "too few poses away from a kink: nothing much was checked";
}

REGISTER_TYPED_TEST_SUITE_P(SurfaceConformance, CellAreasSumToTheNominalArea,
                            ZeroTolerancesGiveZeroVariation, EverySkinModelShapeMeetsItsTolerances,
                            SameSeedGivesTheSameShape, ForceIsContinuousAcrossContactOnset,
                            EvaluateNeverAllocates, ContactBeyondTheAssemblySpace,
                            ARadialJacobianIsTheRadialForcesDerivative);

}  // namespace fitfeel::conformance

// One line per surface plugin, at global scope: a name and the repository-relative path of its
// scenario, and (..._WITH_PLUGINS) an expression giving a folder of plugins the scene needs that
// the registry's default search path lacks, searched first.
#define FITFEEL_SURFACE_CONFORMANCE(Name, scenario_path) \
  FITFEEL_SURFACE_CONFORMANCE_WITH_PLUGINS(Name, scenario_path, std::string())
#define FITFEEL_SURFACE_CONFORMANCE_WITH_PLUGINS(Name, scenario_path, plugin_folder) \
  namespace fitfeel::conformance {                                                   \
  struct Name##ConformanceTraits {                                                   \
    static constexpr const char* kScenario = scenario_path;                          \
    static constexpr int kSeeds = kDefaultSeeds;                                     \
    static std::string PluginFolder() { return plugin_folder; }                      \
  };                                                                                 \
  INSTANTIATE_TYPED_TEST_SUITE_P(Name, SurfaceConformance,                           \
                                 ::testing::Types<Name##ConformanceTraits>);         \
  }                                                                                  \
  static_assert(true, "")
