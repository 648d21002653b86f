#include "framework/core/demand.h"

#include <gtest/gtest.h>

#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"

namespace fitfeel {
namespace {

// The suite runs in the Release preset, which defines NDEBUG: these deaths prove the contract
// checks survive it where assert() would not.
TEST(DemandDeathTest, AbortsWithFileLineAndCondition) {
  const int two = 2;
  EXPECT_DEATH(FITFEEL_DEMAND(two == 3), "demand_test\\.cc:[0-9]+: demand failed: two == 3");
}

TEST(DemandDeathTest, HoldsWhenTrue) {
  const int two = 2;
  FITFEEL_DEMAND(two == 2);
  SUCCEED();
}

class UnpreparedAnalyzer final : public ContactAnalyzer {
 protected:
  void DoPrepare(const PartSpec&, const SkinModelShape&, const PartSpec&, const SkinModelShape&,
                 const ModelSettings&) override {}
  void DoEvaluate(const MatingPose&, ContactState* out) const noexcept override {
    out->engaged = true;
  }
};

class FlatLaw final : public ResistanceLaw {
 protected:
  void DoPrepare(const PartSpec&, const PartSpec&, const ModelSettings&) override {}
  void DoEvaluate(const ContactState&, const MatingMotion&, Wrench* out) const noexcept override {
    out->SetZero();
  }
};

TEST(DemandDeathTest, PublicWrappersCheckTheirContractsInRelease) {
  const UnpreparedAnalyzer analyzer;
  ContactState contact;
  EXPECT_DEATH(analyzer.Evaluate(MatingPose{}, &contact), "demand failed: prepared_");
  const FlatLaw law;
  EXPECT_DEATH(law.Evaluate(contact, MatingMotion{}, nullptr), "demand failed: out != nullptr");
}

}  // namespace
}  // namespace fitfeel
