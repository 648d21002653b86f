#include "framework/tradeoff/tradeoff_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "framework/core/number_text.h"
#include "framework/plot/palette.h"
#include "framework/plot/render.h"

namespace fitfeel::tradeoff {
namespace fs = std::filesystem;
namespace {

// Grid labels hold digits, 'x', '=', '/', '(', ')' and spaces only (grid_ladder.cc and
// tradeoff_study.cc make them); a quote would end the key's string, so none passes.
std::string KeyLabel(const GridRow& r) {
  std::string out;
  for (char c : r.label) out += c == '\'' || c == '"' ? ' ' : c;
  return plot::QuoteForGnuplot(out + " (" + std::to_string(r.inner_cells) + " cells)");
}

double Cost(const GridRow& r, TickCost cost) {
  return cost == TickCost::kP50 ? r.tick_p50_us : r.tick_p99_us;
}

// A cost axis: logarithmic when the costs span more than a decade (prepare times do: milliseconds
// to seconds), else linear with a margin, where a log axis over a fraction of a decade would show
// no tic at all (tick times of a table-driven law differ by tens of percent).
std::string CostAxis(const std::vector<double>& costs) {
  const auto [lo, hi] = std::minmax_element(costs.begin(), costs.end());
  std::ostringstream s;
  if (*hi > 10.0 * *lo) {
    s << "set logscale x\nset xrange [" << ShortestDecimal(*lo / 1.6) << ":"
      << ShortestDecimal(*hi * 1.6) << "]\n";
  } else {
    const double pad = *hi > *lo ? 0.12 * (*hi - *lo) : 0.1 * *hi;
    s << "unset logscale x\nset xrange [" << ShortestDecimal(std::max(0.0, *lo - pad)) << ":"
      << ShortestDecimal(*hi + pad) << "]\n";
  }
  return s.str();
}

// Filled and open variants of a point type, in gnuplot's numbering.
constexpr int kFilled[] = {7, 5, 9, 11, 13, 15};
constexpr int kOpen[] = {6, 4, 8, 10, 12, 14};

std::string Body(const std::vector<GridRow>& rows, const std::string& title, TickCost cost) {
  const GridRow* reference = nullptr;
  std::vector<const GridRow*> compared;
  for (const GridRow& r : rows) {
    if (!(Cost(r, cost) > 0.0) || !std::isfinite(Cost(r, cost))) {
      throw std::invalid_argument("tradeoff chart: grid " + r.label + " has no positive tick time");
    }
    if (r.reference) reference = &r;
    if (!r.reference && r.rms_error_N > 0.0) compared.push_back(&r);
  }
  std::ostringstream s;
  s << "reset\nset encoding utf8\n";
  // Each compared grid is one line, so `every ::k::k` draws it alone in its own colour and point
  // type: the key names the grids, and no label is written beside a point to collide with a
  // neighbour's.
  s << "$errors << EOD\n";
  std::vector<double> prepare, tick;
  for (const GridRow* r : compared) {
    // Prepare times too short for the clock's resolution still need a place on a log axis.
    const double p = std::max(r->prepare_seconds, 1e-6);
    prepare.push_back(p);
    tick.push_back(Cost(*r, cost));
    s << ShortestDecimal(p) << " " << ShortestDecimal(Cost(*r, cost)) << " "
      << ShortestDecimal(r->rms_error_N) << " " << ShortestDecimal(std::max(r->noise_rms_N, 1e-300))
      << "\n";
  }
  s << "EOD\n";
  s << "set multiplot layout 2,1 title " << plot::QuoteForGnuplot(title)
    << " font ',14' margins 0.09,0.68,0.09,0.88 spacing 0.1,0.13\n";
  s << "set grid xtics ytics mxtics mytics lc rgb '#dcdcdc' lw 1 dt solid\n";
  s << "set format x '%g'\nset format y '%g'\n";
  if (compared.empty()) {
    s << "unset key\nset yrange [0:1]\nset xrange [0:1]\n"
         "set label 1 'only the reference: no error to show' at graph 0.5,0.5 center\n"
         "plot 0 with lines lc rgb '#ffffff' notitle\nplot 0 with lines lc rgb '#ffffff' "
         "notitle\nunset multiplot\n";
    return s.str();
  }
  s << "set logscale y\n";
  s << "set ylabel 'RMS error of the mean |fy| trace (N)'\n";
  auto plot = [&](int column, bool key) {
    s << (key ? "set key outside right top vertical Left reverse samplen 1 spacing 1.3 "
                "title 'grid (rows x columns per part)'\n"
              : "unset key\n");
    s << "plot ";
    for (std::size_t k = 0; k < compared.size(); ++k) {
      const unsigned colour = plot::kLineColours[k % plot::kLineColours.size()];
      const std::size_t type = (k / plot::kLineColours.size()) % std::size(kFilled);
      char rgb[16];
      std::snprintf(rgb, sizeof rgb, "'#%06x'", colour);
      s << "$errors every ::" << k << "::" << k << " using " << column << ":3 with points pt "
        << kFilled[type] << " ps 1.5 lc rgb " << rgb << " title " << KeyLabel(*compared[k])
        << ", $errors every ::" << k << "::" << k << " using " << column << ":4 with points pt "
        << kOpen[type] << " ps 1.5 lc rgb " << rgb << " notitle, ";
    }
    s << "NaN with points pt 6 ps 1.5 lc rgb '#505050' title 'open: its sampling noise'\n";
  };
  s << "set title 'against the prepare time (once per scene)'\n";
  s << "set xlabel 'prepare time: median over the seeds (s"
    << (CostAxis(prepare).starts_with("set log") ? ", log scale" : "") << ")'\n";
  s << CostAxis(prepare);
  if (reference != nullptr) {
    s << "set label 2 "
      << plot::QuoteForGnuplot("errors against the finest grid, " + reference->label)
      << " at screen 0.70,0.12 left font ',10'\n";
  }
  plot(1, true);
  s << "unset label 2\n";
  s << "set title 'against the tick compute time (every tick, 1 ms at 1 kHz)'\n";
  s << "set xlabel 'tick compute time: median over the seeds of each run`s "
    << (cost == TickCost::kP50 ? "p50" : "p99") << " (us"
    << (CostAxis(tick).starts_with("set log") ? ", log scale" : "") << ")'\n";
  s << CostAxis(tick);
  plot(2, false);
  s << "unset multiplot\n";
  // A backquote stands for an apostrophe: gnuplot writes one as two inside single quotes.
  std::string body;
  for (char c : s.str()) body += c == '`' ? std::string("''") : std::string(1, c);
  return body;
}

}  // namespace

void RenderTradeoffChart(const std::vector<GridRow>& rows, const std::string& title, TickCost cost,
                         const std::vector<plot::OutputFile>& outputs) {
  if (rows.empty()) throw std::invalid_argument("tradeoff chart: no grid");
  if (outputs.empty()) throw std::invalid_argument("tradeoff chart: no output file");
  const plot::TempDir work;
  plot::RenderScript(Body(rows, title, cost), 1100, 900, outputs, work);
}

}  // namespace fitfeel::tradeoff
