#pragma once

// Resistance laws that render nothing, for the charts that only need a law's pressure per
// interference (or its absence).
#include "framework/model/resistance_law.h"

namespace fitfeel::plot::testing {

// The Lame coefficient of steel, d1 = 20 mm in d2 = 30 mm (docs/oracles.md): 5.8333 MPa per um of
// radial interference.
class LameLaw final : public ResistanceLaw {
 protected:
  void DoPrepare(const PartSpec&, const PartSpec&, const ModelSettings&) override {}
  void DoEvaluate(const ContactState&, const MatingMotion&, Wrench* out) const noexcept override {
    out->SetZero();
  }
  double DoPressurePerInterference() const override { return 5.8333e12; }
};

// A law without a pressure per interference (the ideal geometry's).
class NoPressureLaw final : public ResistanceLaw {
 protected:
  void DoPrepare(const PartSpec&, const PartSpec&, const ModelSettings&) override {}
  void DoEvaluate(const ContactState&, const MatingMotion&, Wrench* out) const noexcept override {
    out->SetZero();
  }
};

}  // namespace fitfeel::plot::testing
