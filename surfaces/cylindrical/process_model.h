#pragma once

#include "framework/model/gps_spec.h"
#include "framework/model/process_spec.h"
#include "framework/model/variation_generator.h"

namespace fitfeel::cylindrical {

struct NormalLaw {
  double mean = 0.0;
  double sd = 0.0;
};

// The size law of a statistical process for limits [lower, upper] (deviations from nominal, any
// unit) of a part in `role`. Requires lower < upper and 0 < cpk <= cp (UserError otherwise).
NormalLaw SizeLaw(const ProcessSpec& process, double lower, double upper, Role role);

// The Rayleigh scale s whose one-sided capability against the tolerance t is `cpk`:
// mean s sqrt(pi/2), sd s sqrt((4 - pi)/2), so s = t / (sqrt(pi/2) + 3 cpk sqrt((4 - pi)/2)).
double FormRayleighScale(double tolerance, double cpk);

// Draws the fraction of its tolerance a form characteristic uses: Rayleigh(FormRayleighScale(1,
// form_cpk)), redrawn while >= 1; each redraw is a rejected part, added to *rejections.
double DrawFormUtilisation(const ProcessSpec& process, Rng& rng, int* rejections);

}  // namespace fitfeel::cylindrical
