#include "framework/view/scene_edits.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"

namespace fitfeel::view {
namespace {

std::string Read(const std::string& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const EditableField* Find(const std::vector<EditableField>& fields, const std::string& path) {
  const auto it = std::find_if(fields.begin(), fields.end(),
                               [&](const EditableField& f) { return f.path == path; });
  return it == fields.end() ? nullptr : &*it;
}

bool Has(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

TEST(SceneEdits, ListsSizesAsIsoClassesWithTheClassesDefinedAtTheirNominalSize) {
  const std::string yaml = Read("scenarios/fits-20mm-h7js6.yaml");
  const std::vector<EditableField> fields = EditableFields(yaml, "fits-20mm-h7js6.yaml");
  const EditableField* shaft = Find(fields, "parts.shaft.size");
  ASSERT_NE(shaft, nullptr);
  EXPECT_EQ(shaft->nominal, "20 mm");
  EXPECT_EQ(shaft->iso_class, "js6");
  for (const char* c : {"g6", "h6", "js6", "k6", "n6", "p6", "s6", "f7", "c11"}) {
    EXPECT_TRUE(Has(shaft->classes, c)) << c;
  }
  EXPECT_FALSE(Has(shaft->classes, "H7"));  // a shaft is offered shaft classes only
  const EditableField* bore = Find(fields, "parts.bushing.size");
  ASSERT_NE(bore, nullptr);
  EXPECT_EQ(bore->iso_class, "H7");
  EXPECT_TRUE(Has(bore->classes, "H7"));
  EXPECT_TRUE(Has(bore->classes, "JS7"));
  EXPECT_FALSE(Has(bore->classes, "g6"));
  for (const char* path : {"parts.shaft.form.roundness", "parts.shaft.form.axis_straightness",
                           "parts.bushing.texture.Rz", "model.friction", "run.seed"}) {
    EXPECT_NE(Find(fields, path), nullptr) << path;
  }
  EXPECT_EQ(Find(fields, "parts.shaft.form.roundness")->value, "10 um");
  EXPECT_EQ(Find(fields, "model.friction")->value, "0.15");
}

TEST(SceneEdits, ListsNoSizeClassesForSizesGivenAsLimits) {
  const std::vector<EditableField> fields =
      EditableFields(Read("scenarios/paper-case1-h7js6.yaml"), "paper-case1-h7js6.yaml");
  const EditableField* shaft = Find(fields, "parts.shaft.size");
  EXPECT_EQ(shaft, nullptr);  // a map of limits, not one scalar: not offered
}

TEST(SceneEdits, OffersThePreferredFitsThatIso286DefinesAtTheSize) {
  const std::vector<std::string> fits = FitsAt(0.020);
  for (const char* fit :
       {"H7/g6", "H7/h6", "H7/js6", "H7/k6", "H7/n6", "H7/p6", "H7/s6", "H11/c11", "H7/u6"}) {
    EXPECT_TRUE(Has(fits, fit)) << fit;
  }
  EXPECT_TRUE(FitsAt(0.6).empty());  // ISO 286's tables end at 500 mm
}

TEST(SceneEdits, AnEditedClassLoadsWithTheStandardsLimits) {
  const std::string yaml = Read("scenarios/fits-20mm-h7js6.yaml");
  const std::string edited = ApplyEdits(yaml, "fits.yaml",
                                        {{"parts.shaft.size", "20 mm k6"},
                                         {"parts.shaft.form.roundness", "5 um"},
                                         {"model.friction", "0.2"},
                                         {"run.seed", "7"}});
  const Scene scene = LoadSceneFromYaml(edited, "fits.yaml", test_support::BuildTreePlugins());
  // ISO 286-2, 18-30 mm: k6 is +2 / +15 um.
  EXPECT_EQ(scene.inner.size.iso_code, "k6");
  EXPECT_NEAR(scene.inner.size.lower_deviation, 2e-6, 1e-12);
  EXPECT_NEAR(scene.inner.size.upper_deviation, 15e-6, 1e-12);
  EXPECT_NEAR(scene.model.friction, 0.2, 1e-15);
  EXPECT_EQ(scene.run.seed, 7u);
  // Everything else as the file gives it.
  const Scene before = LoadSceneFromYaml(yaml, "fits.yaml", test_support::BuildTreePlugins());
  EXPECT_EQ(scene.outer.size.iso_code, before.outer.size.iso_code);
  EXPECT_EQ(scene.run.duration, before.run.duration);
  EXPECT_EQ(scene.device_id, before.device_id);
}

TEST(SceneEdits, RefusesAKeyThePageMayNotChangeNamingIt) {
  const std::string yaml = Read("scenarios/fits-20mm-h7js6.yaml");
  try {
    ApplyEdits(yaml, "fits.yaml", {{"device.speed", "1 m/s"}});
    FAIL() << "an edit of the device was taken";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "device.speed");
    EXPECT_NE(std::string(e.what()).find("parts.shaft.size"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ApplyEdits(yaml, "fits.yaml", {{"model.friction", "0.1\nrun: {}"}}), ScenarioError);
}

TEST(SceneEdits, ABadValueIsRefusedByTheLoaderAtItsKey) {
  const std::string edited = ApplyEdits(Read("scenarios/fits-20mm-h7js6.yaml"), "fits.yaml",
                                        {{"parts.shaft.size", "20 mm q6"}});
  try {
    LoadSceneFromYaml(edited, "fits.yaml", test_support::BuildTreePlugins());
    FAIL() << "q6 was taken";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "parts.shaft.size");
    EXPECT_GT(e.where().line, 0);
  }
}

}  // namespace
}  // namespace fitfeel::view
