#include "surfaces/common/column_response_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/core/parallel.h"

namespace fitfeel {

ColumnResponseTable::ColumnResponseTable(int steps, int columns, int samples,
                                         const ExpectedInterferenceTable& texture)
    : steps_(steps), columns_(columns), samples_(samples), texture_(texture) {
  if (samples < 2) throw std::invalid_argument("a column response table needs >= 2 samples");
  if (steps < 1 || columns < 1) {
    throw std::invalid_argument("a column response table needs steps and columns");
  }
  const auto entries = static_cast<std::size_t>(steps) * static_cast<std::size_t>(columns);
  entries_.assign(entries, Entry{});
  touch_from_.assign(entries, std::numeric_limits<double>::infinity());
  values_.resize(entries * static_cast<std::size_t>(samples) * 3);
}

std::size_t ColumnResponseTable::bytes() const {
  return entries_.size() * sizeof(Entry) + (touch_from_.size() + values_.size()) * sizeof(double);
}

ColumnResponse ColumnResponseTable::Exact(std::span<const ColumnCell> cells,
                                          const ExpectedInterferenceTable& texture,
                                          double x) noexcept {
  ColumnResponse r;
  for (const ColumnCell& c : cells) {
    const double delta = texture(c.gap - c.cosine * x);
    if (delta > 0.0) {
      r.volume += c.area * delta;
      r.resultant += c.area * c.cosine * delta;
      r.max = std::max(r.max, delta);
    }
  }
  return r;
}

void ColumnResponseTable::Fill(int step, int column, std::span<const ColumnCell> cells) {
  const std::size_t index = static_cast<std::size_t>(step) * columns_ + column;
  Entry& e = entries_[index];
  e = Entry{};
  touch_from_[index] = std::numeric_limits<double>::infinity();
  if (cells.empty()) return;
  double x_lo = std::numeric_limits<double>::infinity();
  double x_hi = -std::numeric_limits<double>::infinity();
  for (const ColumnCell& c : cells) {
    if (!(c.cosine > 0.0)) throw std::invalid_argument("column cell with a non-positive cosine");
    x_lo = std::min(x_lo, (c.gap - texture_.upper()) / c.cosine);
    x_hi = std::max(x_hi, (c.gap - texture_.lower()) / c.cosine);
    e.volume_slope += c.area * c.cosine;
    e.resultant_slope += c.area * c.cosine * c.cosine;
    e.max_cosine = std::max(e.max_cosine, c.cosine);
  }
  // A sharp single-gap column has x_lo == x_hi: the sums are 0 below and linear above, which a
  // range of one rounding unit reproduces.
  x_hi = std::max(x_hi, x_lo + 1e-15);
  double at_hi = -std::numeric_limits<double>::infinity();
  for (const ColumnCell& c : cells) {
    const double intercept = texture_.mean() - c.gap;
    const double value = intercept + c.cosine * x_hi;
    if (value > at_hi || (value == at_hi && c.cosine > e.max_slope_a)) {
      at_hi = value;
      e.max_slope_a = c.cosine;
      e.max_intercept_a = intercept;
    }
    if (c.cosine > e.max_slope_b || (c.cosine == e.max_slope_b && intercept > e.max_intercept_b)) {
      e.max_slope_b = c.cosine;
      e.max_intercept_b = intercept;
    }
  }
  e.empty = false;
  e.x_lo = x_lo;
  touch_from_[index] = x_lo;
  e.x_hi = x_hi;
  e.inv_dx = (samples_ - 1) / (x_hi - x_lo);
  double* v = &values_[index * static_cast<std::size_t>(samples_) * 3];
  std::fill(v, v + 3 * samples_, 0.0);
  const double dx = (x_hi - x_lo) / (samples_ - 1);
  auto sample = [&](int m) { return m + 1 == samples_ ? x_hi : x_lo + m * dx; };
  const double upper = texture_.upper(), lower = texture_.lower(), mean = texture_.mean();
  // Cell by cell, from its first touching sample on; past the texture's lower limit a cell's
  // interference is the line mean - gap, which needs no table lookup. Each sample's sums add the
  // cells in their order, as Exact does.
  for (const ColumnCell& c : cells) {
    int m = std::clamp(static_cast<int>(((c.gap - upper) / c.cosine - x_lo) / dx), 0, samples_);
    while (m > 0 && c.gap - c.cosine * sample(m - 1) < upper) --m;
    for (; m < samples_; ++m) {
      const double gap = c.gap - c.cosine * sample(m);
      const double delta = gap <= lower ? mean - gap : texture_(gap);
      if (!(delta > 0.0)) continue;
      v[3 * m] += c.area * delta;
      v[3 * m + 1] += c.area * c.cosine * delta;
      v[3 * m + 2] = std::max(v[3 * m + 2], delta);
    }
  }
}

void ColumnResponseTable::FillAll(
    const std::function<void(int step, int column, std::vector<ColumnCell>* cells)>& cells) {
  std::vector<int> steps(static_cast<std::size_t>(steps_));
  for (int k = 0; k < steps_; ++k) steps[static_cast<std::size_t>(k)] = k;
  FillSteps(steps, cells);
}

void ColumnResponseTable::FillSteps(
    const std::vector<int>& steps,
    const std::function<void(int step, int column, std::vector<ColumnCell>* cells)>& cells) {
  for (int k : steps) {
    if (k < 0 || k >= steps_) throw std::invalid_argument("column response table: no such step");
  }
  ParallelFor(static_cast<int>(steps.size()), [&](int begin, int end) {
    std::vector<ColumnCell> column_cells;
    for (int i = begin; i < end; ++i) {
      const int k = steps[static_cast<std::size_t>(i)];
      for (int j = 0; j < columns_; ++j) {
        cells(k, j, &column_cells);
        Fill(k, j, column_cells);
      }
    }
  });
}

void ColumnResponseTable::Blend(int a, int b, double t, const Eigen::Matrix2Xd& directions,
                                const Eigen::Vector2d& offset, double shift,
                                ContactState* out) const noexcept {
  // Most columns of a cone or a sphere touch nothing at a given pose (a settled part bears on one
  // side): a pass over the two steps' contiguous thresholds skips them before At reads an entry.
  // Skipped columns are those At answers with zeros for both steps, so the sums are unchanged.
  const double* from_a = touch_from_.data() + static_cast<std::size_t>(a) * columns_;
  const double* from_b = touch_from_.data() + static_cast<std::size_t>(b) * columns_;
  // The resultant's Jacobian: column j's resultant is a function of x_j = offset . u_j, so it adds
  // its slope in x times u_j u_j' (symmetric: three sums).
  double jxx = 0.0, jxz = 0.0, jzz = 0.0;
  for (int j = 0; j < columns_; ++j) {
    const double x = offset.dot(directions.col(j)) - shift;
    if (!(x > from_a[j]) && !(x > from_b[j])) continue;
    double slope_p = 0.0, slope_q = 0.0;
    const ColumnResponse p = At(a, j, x, &slope_p);
    const ColumnResponse q = At(b, j, x, &slope_q);
    const double volume = p.volume + t * (q.volume - p.volume);
    if (!(volume > 0.0)) continue;
    out->interference_volume += volume;
    out->pressure_resultant += (p.resultant + t * (q.resultant - p.resultant)) * directions.col(j);
    out->max_interference = std::max(out->max_interference, p.max + t * (q.max - p.max));
    const double slope = slope_p + t * (slope_q - slope_p);
    const double ux = directions(0, j), uz = directions(1, j);
    jxx += slope * ux * ux;
    jxz += slope * ux * uz;
    jzz += slope * uz * uz;
  }
  out->interference = out->interference_volume > 0.0;
  out->resultant_jacobian << jxx, jxz, jxz, jzz;
}

ColumnResponse ColumnResponseTable::At(int step, int column, double x,
                                       double* resultant_slope) const noexcept {
  const std::size_t index = static_cast<std::size_t>(step) * columns_ + column;
  const Entry& e = entries_[index];
  ColumnResponse r;
  if (e.empty || !(x > e.x_lo)) return r;
  const double* v = &values_[index * static_cast<std::size_t>(samples_) * 3];
  const double u = (x - e.x_lo) * e.inv_dx;
  if (u >= samples_ - 1) {
    const double* last = v + 3 * (samples_ - 1);
    const double beyond = x - e.x_hi;
    r.volume = last[0] + e.volume_slope * beyond;
    r.resultant = last[1] + e.resultant_slope * beyond;
    r.max = std::max(e.max_intercept_a + e.max_slope_a * x, e.max_intercept_b + e.max_slope_b * x);
    if (resultant_slope != nullptr) *resultant_slope = e.resultant_slope;
    return r;
  }
  const int m = static_cast<int>(u);
  const double f = u - m;
  const double* a = v + 3 * m;
  r.volume = a[0] + f * (a[3] - a[0]);
  r.resultant = a[1] + f * (a[4] - a[1]);
  r.max = a[2] + f * (a[5] - a[2]);
  if (resultant_slope != nullptr) *resultant_slope = (a[4] - a[1]) * e.inv_dx;
  return r;
}

double ColumnResponseTable::VolumeErrorBound(int step, int column) const {
  const Entry& e = entry(step, column);
  if (e.empty) return 0.0;
  const double dx = (e.x_hi - e.x_lo) / (samples_ - 1);
  // Per cell area * cosine * min(dx^2 f_max cosine / 8, dx / 4): the chord of a convex function
  // departs from it by at most its second derivative times dx^2 / 8, and by at most a quarter of
  // its slope change over the interval (area * cosine in all) times dx.
  return e.volume_slope * std::min(dx * dx * texture_.max_density() * e.max_cosine / 8.0, dx / 4.0);
}

}  // namespace fitfeel
