#pragma once

namespace fitfeel::cylindrical {

// sum of a[k] b[k] over [0, n), in eight fixed lanes combined in a fixed order, compiled also for
// AVX2 and AVX-512 (framework/core/simd_clones.h): the same sum on every machine, where a
// compiler's own vectorised reduction would add in an order that depends on the vector width. For
// prepare-time inner products (a resampling's, a dense factor's back substitution).
double FixedLaneDot(const double* a, const double* b, int n);

}  // namespace fitfeel::cylindrical
