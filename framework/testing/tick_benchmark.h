#pragma once

// What a surface plugin's tick benchmark is made of, header-only: the pair's contact analyzer and
// law prepared on freshly drawn skin model shapes, and the loop that times one tick (the
// analyzer's Evaluate, then the law's). The plugin's own classes are template arguments, so the
// calls are as direct as in the stage.

#include <benchmark/benchmark.h>

#include "framework/core/wrench.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/discretizer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/model_settings.h"
#include "framework/model/resistance_law.h"
#include "framework/model/variation_generator.h"

namespace fitfeel::test_support {

// The grid a benchmark's first two arguments give: rows, columns.
inline Resolution BenchmarkGrid(const benchmark::State& state) {
  return Resolution{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
}

// Prepares `analyzer` and `law` for the pair on skin model shapes of `grid`, drawn from seed 1
// (inner first) with the texture's expected interference in the analyzer.
template <class Discretizer, class Generator, class Analyzer, class Law>
void PreparePair(const PartSpec& inner, const PartSpec& outer, const Resolution& grid,
                 const ModelSettings& settings, Analyzer* analyzer, Law* law) {
  Rng rng(1);
  const SkinModelShape inner_sms = Generator().Generate(
      inner, Discretizer().Discretize(inner, grid), TextureMode::kExpected, rng);
  const SkinModelShape outer_sms = Generator().Generate(
      outer, Discretizer().Discretize(outer, grid), TextureMode::kExpected, rng);
  analyzer->Prepare(inner, inner_sms, outer, outer_sms, settings);
  law->Prepare(inner, outer, settings);
}

// The timed loop: per iteration the pose next_pose() gives, through the analyzer and the law at
// `motion`.
template <class Analyzer, class Law, class NextPose>
void TimeTicks(benchmark::State& state, const Analyzer& analyzer, const Law& law,
               const MatingMotion& motion, NextPose&& next_pose) {
  ContactState contact;
  Wrench wrench;
  for (auto _ : state) {
    const MatingPose pose = next_pose();
    analyzer.Evaluate(pose, &contact);
    law.Evaluate(contact, motion, &wrench);
    benchmark::DoNotOptimize(wrench);
  }
}

}  // namespace fitfeel::test_support
