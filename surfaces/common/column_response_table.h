#pragma once

#include <functional>
#include <memory>
#include <new>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "framework/model/contact_analyzer.h"
#include "framework/model/texture_contact.h"

namespace fitfeel {

// One cell of a column of a Winkler bed (every cell's pressure proportional to its own
// interference), as seen by a radial offset of the moving part: the cell's gap is
// `gap - cosine * x`, where x is the offset's projection on the column's direction u_j (the cell's
// normal projected on the cross-section is cosine * u_j; 1 for a cylinder or a cone, cos(latitude)
// on a sphere).
struct ColumnCell {
  double area = 0.0;    // m^2
  double cosine = 1.0;  // > 0
  double gap = 0.0;     // at x = 0, m
};

// What a column of cells gives at one offset projection x, with delta = T(gap - cosine * x) the
// (expected) interference of each cell:
struct ColumnResponse {
  double volume = 0.0;     // sum area * delta, m^3
  double resultant = 0.0;  // sum area * cosine * delta, m^3 (along u_j)
  double max = 0.0;        // largest delta, m
};

// The response of many columns (entries: steps of a pose parameter such as depth or rotation,
// times columns) as functions of x, tabulated in prepare so that a tick costs O(1) per column
// instead of O(cells). Each entry samples its three sums at `samples` equally spaced x over the
// range where they are not simple: below x_lo = min (gap - upper) / cosine no cell touches (all
// zero), above x_hi = max (gap - lower) / cosine every cell is past the texture's lower limit and
// the volume and resultant are linear in x (slopes sum area * cosine and sum area * cosine^2),
// extrapolated exactly from x_hi. Between samples the sums are interpolated linearly, so they stay
// continuous and nondecreasing in x. E[(X - g)+] is convex in g with second derivative the density
// of X (at most f_max), so a chord departs from it by at most dx^2 f_max / 8 times its curvature
// weight, or a quarter of its slope change times dx (the bound for a sharp contact's kink): per
// entry, the volume's interpolation error is at most
//   sum(area * cosine) * min(dx^2 f_max max(cosine) / 8, dx / 4)          (VolumeErrorBound)
// and the resultant's no more (its weights carry one more cosine <= 1).
// The largest interference is interpolated the same way; beyond x_hi it is the larger of two of
// the cells' lines mean - gap + cosine * x: the one that is largest at x_hi and the steepest (exact
// when the upper envelope of the lines beyond x_hi has at most these two pieces, as with equal
// gaps or equal cosines; otherwise below the exact value by less than the envelope's bend).
class ColumnResponseTable {
 public:
  ColumnResponseTable() = default;
  // Throws std::invalid_argument for fewer than 2 samples or a non-positive entry count.
  ColumnResponseTable(int steps, int columns, int samples,
                      const ExpectedInterferenceTable& texture);

  int steps() const { return steps_; }
  int columns() const { return columns_; }
  int samples() const { return samples_; }
  std::size_t bytes() const;

  // Prepare: tabulates entry (step, column) from its cells (an empty span is a column that touches
  // nothing). Distinct entries may be filled from different threads. Throws std::invalid_argument
  // for a non-positive cosine.
  void Fill(int step, int column, std::span<const ColumnCell> cells);

  // Prepare: fills every entry from cells(step, column, &cells), on PrepareThreads() threads
  // (framework/core/parallel.h) over the steps; the same tables bit for bit for any count.
  void FillAll(
      const std::function<void(int step, int column, std::vector<ColumnCell>* cells)>& cells);
  // The same for the entries of `steps` only (each in range); the others stay empty, answering no
  // contact, so no tick may read them.
  void FillSteps(
      const std::vector<int>& steps,
      const std::function<void(int step, int column, std::vector<ColumnCell>* cells)>& cells);

  // Per tick: no allocation. `step` and `column` must be in range. `resultant_slope`, when given,
  // receives d(resultant)/dx of the piece x lies on (0 where the entry does not touch).
  ColumnResponse At(int step, int column, double x,
                    double* resultant_slope = nullptr) const noexcept;
  // Per tick: adds to `out` the columns' sums at x_j = offset . u_j - shift (u_j the columns of
  // `directions`), blended linearly between steps `a` and `b` with weight t of b: the interference
  // volume, the resultant sum (along u_j) and the largest interference; sets out->interference and
  // out->resultant_jacobian, the sum of each column's blended slope d(resultant)/dx times
  // u_j u_j' (the interpolation's own: exact between samples, one-sided on a sample).
  void Blend(int a, int b, double t, const Eigen::Matrix2Xd& directions,
             const Eigen::Vector2d& offset, double shift, ContactState* out) const noexcept;
  // The worst-case interpolation error bound above for the volume of entry (step, column), m^3.
  double VolumeErrorBound(int step, int column) const;

  // The sums computed cell by cell (the oracle the table approximates).
  static ColumnResponse Exact(std::span<const ColumnCell> cells,
                              const ExpectedInterferenceTable& texture, double x) noexcept;

 private:
  struct Entry {
    double x_lo = 0.0;
    double x_hi = 0.0;
    double inv_dx = 0.0;
    double volume_slope = 0.0;     // sum area * cosine
    double resultant_slope = 0.0;  // sum area * cosine^2
    double max_cosine = 0.0;
    // Lines slope * x + intercept of the largest interference beyond x_hi.
    double max_slope_a = 0.0, max_intercept_a = 0.0;
    double max_slope_b = 0.0, max_intercept_b = 0.0;
    bool empty = true;
  };
  const Entry& entry(int step, int column) const {
    return entries_[static_cast<std::size_t>(step) * columns_ + column];
  }

  int steps_ = 0, columns_ = 0, samples_ = 0;
  ExpectedInterferenceTable texture_;
  std::vector<Entry> entries_;
  // Per entry, its x_lo (infinity when empty): below it the entry is zero. Apart from the
  // entries so that Blend's scan for touching columns reads 8 bytes a column, not an Entry.
  std::vector<double> touch_from_;
  // Leaves a double it makes unset: Fill writes every value of an entry it fills and an empty
  // entry's are never read, so a table filled for a few steps (FillSteps) never touches the rest
  // of its memory.
  template <class T>
  struct UnsetAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
      using other = UnsetAllocator<U>;
    };
    template <class U>
    void construct(U* p) noexcept {
      ::new (static_cast<void*>(p)) U;
    }
  };
  // Per entry, `samples` triples (volume, resultant, max), contiguous.
  std::vector<double, UnsetAllocator<double>> values_;
};

}  // namespace fitfeel
