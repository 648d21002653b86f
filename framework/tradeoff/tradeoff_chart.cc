#include "framework/tradeoff/tradeoff_chart.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "framework/core/number_text.h"
#include "framework/plot/render.h"

namespace fitfeel::tradeoff {
namespace fs = std::filesystem;
namespace {

// Grid labels hold digits, 'x', '=', '/', '(', ')' and spaces only (grid_ladder.cc and
// tradeoff_study.cc make them), so double quotes delimit them safely in a data block.
std::string DataLabel(const std::string& label) {
  std::string out;
  for (char c : label) out += c == '"' ? '\'' : c;
  return "\"" + out + "\"";
}

// Labels of every other point below it rather than above, so that neighbours stay apart. Only
// for a block of two or more points: gnuplot warns about an empty selection.
std::string AlternateLabels(const std::string& block) {
  return ", " + block +
         " every 2::1 using 1:2:4 with labels left offset 0.8,-0.9 font ',10' notitle";
}

double Cost(const GridRow& r, TickCost cost) {
  return cost == TickCost::kP50 ? r.tick_p50_us : r.tick_p99_us;
}

std::string Body(const std::vector<GridRow>& rows, const std::string& title, TickCost cost) {
  double x_min = Cost(rows.front(), cost), x_max = x_min, ref_mean = 0.0, y_max = 0.0;
  for (const GridRow& r : rows) {
    if (!(Cost(r, cost) > 0.0) || !std::isfinite(Cost(r, cost))) {
      throw std::invalid_argument("tradeoff chart: grid " + r.label + " has no positive tick time");
    }
    x_min = std::min(x_min, Cost(r, cost));
    x_max = std::max(x_max, Cost(r, cost));
    if (r.reference) ref_mean = r.mean_axial_N;
    y_max = std::max(y_max, r.mean_axial_N + r.sd_axial_N);
  }
  std::ostringstream s;
  s << "reset\nset encoding utf8\n";
  s << "$grids << EOD\n";
  for (const GridRow& r : rows) {
    s << ShortestDecimal(Cost(r, cost)) << " " << ShortestDecimal(r.mean_axial_N) << " "
      << ShortestDecimal(r.sd_axial_N) << " " << DataLabel(r.label) << "\n";
  }
  s << "EOD\n$errors << EOD\n";
  int errors = 0;
  for (const GridRow& r : rows) {
    if (r.reference || !(r.rms_error_N > 0.0)) continue;
    ++errors;
    s << ShortestDecimal(Cost(r, cost)) << " " << ShortestDecimal(r.rms_error_N) << " "
      << ShortestDecimal(std::max(r.noise_rms_N, 1e-300)) << " " << DataLabel(r.label) << "\n";
  }
  s << "EOD\n";
  s << "set multiplot layout 2,1 title " << plot::QuoteForGnuplot(title) << " font ',14'\n";
  s << "set lmargin 12\nset rmargin 6\n";
  s << "set grid xtics ytics mxtics lc rgb '#c8c8c8' lw 1 dt solid\n";
  s << "set logscale x\nset xrange [" << ShortestDecimal(x_min / 1.6) << ":"
    << ShortestDecimal(x_max * 1.6) << "]\n";
  s << "set key below\n";
  s << "set xtics (0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000)\n";
  s << "set xlabel 'tick compute time: median over the seeds of each run`s "
    << (cost == TickCost::kP50 ? "p50" : "p99") << " (us, log scale)'\n";
  s << "set ylabel 'mean axial resistance (N)'\n";
  // |fy| is never negative: a bar below zero only says how wide the spread is.
  s << "set yrange [0:" << ShortestDecimal(y_max > 0.0 ? 1.08 * y_max : 1.0) << "]\n";
  s << "set title 'Mean |fy| over the constrained ticks: mean over seeds, bars +-1 seed-to-seed "
       "SD'\n";
  s << "plot $grids using 1:2:3 with yerrorbars pt 7 ps 1.2 lw 1.5 lc rgb '#3b528b' "
       "title 'grid (rows x columns per part), mean +-1 SD over seeds', "
    << ShortestDecimal(ref_mean)
    << " with lines dt 2 lw 1.5 lc rgb '#5ec962' title 'finest grid (reference)', "
       "$grids every 2 using 1:2:4 with labels left offset 0.8,0.9 font ',10' notitle"
    << (rows.size() > 1 ? AlternateLabels("$grids") : "") << "\n";
  s << "set yrange [*:*]\nset logscale y\n";
  s << "set ylabel 'RMS error (N, log scale)'\n";
  s << "set title 'Seed-averaged axial trace against the reference: RMS over the constrained "
       "ticks'\n";
  if (errors > 0) {
    s << "plot $errors using 1:2 with points pt 7 ps 1.2 lw 1.5 lc rgb '#3b528b' "
         "title 'RMS |mean fy - mean fy_ref|', "
         "$errors using 1:3 with points pt 6 lw 1.2 lc rgb '#b5367a' "
         "title 'sampling noise (RMS paired standard error of the difference)', "
         "$errors every 2 using 1:2:4 with labels left offset 0.8,0.9 font ',10' notitle"
      << (errors > 1 ? AlternateLabels("$errors") : "") << "\n";
  } else {
    s << "unset logscale y\nset yrange [0:1]\n"
         "set label 1 'only the reference: no error to show' at graph 0.5,0.5 center\n"
         "plot 0 with lines lc rgb '#ffffff' notitle\n";
  }
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
