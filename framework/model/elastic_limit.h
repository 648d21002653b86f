#pragma once

#include "framework/core/export.h"

namespace fitfeel {

// Elastic limits of press-fit parts after DIN 7190-1 (docs/elastic-limit.md). Pressures in Pa,
// diameters in m; each throws UserError for diameters that do not nest or a yield strength <= 0.
//
// Hub (outer part) of bore d and outer diameter D: the equivalent stress at the bore reaches the
// yield strength R_e at
//   p_F = (1 - Q^2) R_e / sqrt(3),   Q = d / D
// (von Mises with the axial stress midway between the radial and hoop stresses, as DIN 7190 takes
// it: sigma_v = sqrt(3) (sigma_t - sigma_r) / 2 = sqrt(3) p / (1 - Q^2)).
FITFEEL_API double HubYieldPressure(double d, double outer_diameter, double yield_strength);
// Shaft (inner part) of diameter d with a bore d_i: the same form at its bore, Q_i = d_i / d.
// A solid shaft is in equal biaxial compression, sigma_r = sigma_t = -p, which DIN's form counts
// as no shear at all; the plane-stress von Mises stress is then p, so p_F = R_e is taken.
FITFEEL_API double ShaftYieldPressure(double d, double bore, double yield_strength);
// Largest peak pressure p0 of an elastic Hertz contact before the material under it yields:
// first yield lies below the surface at p0 = 1.61 R_e (von Mises, nu = 0.3; Johnson, Contact
// Mechanics, 1985, section 6.2), for a point (circular) contact.
FITFEEL_API double HertzYieldPeakPressure(double yield_strength);

}  // namespace fitfeel
