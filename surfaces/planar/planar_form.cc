#include "surfaces/planar/planar_form.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "framework/core/demand.h"

namespace fitfeel::planar {
namespace {

double RangeOfLine(const std::vector<double>& t, const std::vector<double>& v, double s) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double r = v[k] - s * t[k];
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return hi - lo;
}

// Cross product of (b - a) and (c - a) in the (t, v) plane.
double Cross(double at, double av, double bt, double bv, double ct, double cv) {
  return (bt - at) * (cv - av) - (bv - av) * (ct - at);
}

}  // namespace

LineZone MinZoneStraightness(const std::vector<double>& t, const std::vector<double>& v) {
  FITFEEL_DEMAND(t.size() == v.size());
  LineZone zone;
  if (t.empty()) return zone;
  std::vector<std::size_t> order(t.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return t[a] != t[b] ? t[a] < t[b] : v[a] < v[b]; });
  if (t[order.front()] == t[order.back()]) {
    zone.width = v[order.back()] - v[order.front()];
    return zone;
  }
  // Andrew's monotone chain: lower and upper hulls; their edge slopes are the candidates.
  std::vector<std::size_t> lower, upper;
  for (std::size_t k : order) {
    while (lower.size() >= 2 && Cross(t[lower[lower.size() - 2]], v[lower[lower.size() - 2]],
                                      t[lower.back()], v[lower.back()], t[k], v[k]) <= 0.0) {
      lower.pop_back();
    }
    lower.push_back(k);
    while (upper.size() >= 2 && Cross(t[upper[upper.size() - 2]], v[upper[upper.size() - 2]],
                                      t[upper.back()], v[upper.back()], t[k], v[k]) >= 0.0) {
      upper.pop_back();
    }
    upper.push_back(k);
  }
  zone.width = std::numeric_limits<double>::infinity();
  for (const auto* hull : {&lower, &upper}) {
    for (std::size_t e = 1; e < hull->size(); ++e) {
      const std::size_t a = (*hull)[e - 1], b = (*hull)[e];
      if (t[b] == t[a]) continue;
      const double s = (v[b] - v[a]) / (t[b] - t[a]);
      const double w = RangeOfLine(t, v, s);
      if (w < zone.width) {
        zone.width = w;
        zone.slope = s;
      }
    }
  }
  return zone;
}

double RangeAlong(const std::vector<double>& y, const std::vector<double>& z,
                  const std::vector<double>& v, double a, double c) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (std::size_t k = 0; k < y.size(); ++k) {
    const double r = v[k] - a * y[k] - c * z[k];
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return y.empty() ? 0.0 : hi - lo;
}

PlaneZone MinZoneFlatness(const std::vector<double>& y, const std::vector<double>& z,
                          const std::vector<double>& v) {
  FITFEEL_DEMAND(y.size() == z.size() && y.size() == v.size());
  PlaneZone zone;
  if (y.empty()) return zone;
  const auto [ymin, ymax] = std::minmax_element(y.begin(), y.end());
  const auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
  const double span = *ymax - *ymin;
  const double range = *vmax - *vmin;
  std::vector<double> w(v.size());
  auto best_over_c = [&](double a, double* c) {
    for (std::size_t k = 0; k < v.size(); ++k) w[k] = v[k] - a * y[k];
    const LineZone line = MinZoneStraightness(z, w);
    *c = line.slope;
    return line.width;
  };
  if (span == 0.0 || range == 0.0) {
    zone.width = best_over_c(0.0, &zone.slope_z);
    return zone;
  }
  // Beyond |a| = 2 range / span the points of equal z at the two ends of the face alone spread
  // wider than the whole face does at a = 0, so the minimiser lies inside this bracket.
  double lo = -2.0 * range / span, hi = 2.0 * range / span;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c1 = 0.0, c2 = 0.0;
  double a1 = hi - g * (hi - lo), a2 = lo + g * (hi - lo);
  double f1 = best_over_c(a1, &c1), f2 = best_over_c(a2, &c2);
  for (int it = 0; it < 160 && hi - lo > 1e-22 * (range / span); ++it) {
    if (f1 <= f2) {
      hi = a2;
      a2 = a1;
      f2 = f1;
      a1 = hi - g * (hi - lo);
      f1 = best_over_c(a1, &c1);
    } else {
      lo = a1;
      a1 = a2;
      f1 = f2;
      a2 = lo + g * (hi - lo);
      f2 = best_over_c(a2, &c2);
    }
  }
  zone.slope_y = 0.5 * (lo + hi);
  zone.width = best_over_c(zone.slope_y, &zone.slope_z);
  return zone;
}

}  // namespace fitfeel::planar
