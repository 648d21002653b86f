#include "framework/stability/stability_chart.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "framework/core/number_text.h"
#include "framework/plot/render.h"

namespace fitfeel {
namespace {

// Above the direct rendering's point of the same rate, by a factor a log axis shows as a small
// fixed step: both methods' outcomes stay visible at one (K, rate).
constexpr double kCoupledLift = 1.08;

std::string Body(const std::vector<StabilityMapRow>& rows, double b, const std::string& title,
                 int* height) {
  std::vector<double> dampings;
  double k_lo = rows.front().stiffness, k_hi = k_lo, r_lo = rows.front().rate, r_hi = r_lo;
  for (const StabilityMapRow& r : rows) {
    if (std::find(dampings.begin(), dampings.end(), r.damping) == dampings.end()) {
      dampings.push_back(r.damping);
    }
    k_lo = std::min(k_lo, r.stiffness);
    k_hi = std::max(k_hi, r.stiffness);
    r_lo = std::min(r_lo, r.rate);
    r_hi = std::max(r_hi, r.rate);
  }
  std::sort(dampings.begin(), dampings.end());
  std::ostringstream s;
  s << "reset\nset encoding utf8\n";
  // One block per damping and outcome, so each plot command selects by block, not by comparing
  // numbers read back from text.
  auto block = [&](std::size_t d, RenderingMethod method, bool stable) {
    std::string name = "$d" + std::to_string(d) + (method == RenderingMethod::kDirect ? "d" : "c") +
                       (stable ? "s" : "u");
    s << name << " << EOD\n";
    bool any = false;
    for (const StabilityMapRow& r : rows) {
      if (r.damping != dampings[d] || r.method != method || r.outcome.stable != stable) continue;
      const double lift = method == RenderingMethod::kCoupled ? kCoupledLift : 1.0;
      s << ShortestDecimal(r.stiffness) << " " << ShortestDecimal(r.rate * lift) << "\n";
      any = true;
    }
    // gnuplot warns about an empty block (and a warning fails the render): a point off the axes.
    if (!any) s << "1e-300 1e-300\n";
    s << "EOD\n";
    return name;
  };
  std::vector<std::array<std::string, 4>> names;
  for (std::size_t d = 0; d < dampings.size(); ++d) {
    names.push_back(
        {block(d, RenderingMethod::kDirect, true), block(d, RenderingMethod::kDirect, false),
         block(d, RenderingMethod::kCoupled, true), block(d, RenderingMethod::kCoupled, false)});
  }
  const int panels = static_cast<int>(dampings.size());
  *height = 90 + 330 * panels;
  s << "set multiplot layout " << panels << ",1 title " << plot::QuoteForGnuplot(title)
    << " font ',14'\n";
  s << "set lmargin 12\nset rmargin 34\n";
  s << "set logscale xy\nset format x '%g'\nset format y '%g'\n";
  s << "set grid xtics ytics lc rgb '#dcdcdc' lw 1 dt solid\n";
  s << "set xrange [" << ShortestDecimal(k_lo / 1.5) << ":" << ShortestDecimal(k_hi * 1.5)
    << "]\nset yrange [" << ShortestDecimal(r_lo / 1.4) << ":" << ShortestDecimal(r_hi * 1.4)
    << "]\n";
  // A tic at every swept rate: a log axis over one decade would label only 1000.
  std::vector<double> rates;
  for (const StabilityMapRow& r : rows) {
    if (std::find(rates.begin(), rates.end(), r.rate) == rates.end()) rates.push_back(r.rate);
  }
  std::sort(rates.begin(), rates.end());
  s << "set ytics (";
  for (std::size_t k = 0; k < rates.size(); ++k) s << (k ? ", " : "") << ShortestDecimal(rates[k]);
  s << ")\n";
  s << "set xlabel 'contact stiffness at the device K (N/m)'\nset ylabel 'rate 1/T (Hz)'\n";
  s << "set key outside right top vertical Left reverse samplen 1 spacing 1.2\n";
  s << "set parametric\nset trange [" << ShortestDecimal(r_lo / 1.4) << ":"
    << ShortestDecimal(r_hi * 1.4) << "]\n";
  for (std::size_t d = 0; d < dampings.size(); ++d) {
    const double B = dampings[d];
    s << "set title "
      << plot::QuoteForGnuplot("virtual damping B = " + MessageNumber(B) +
                               " N*s/m (device damping b = " + MessageNumber(b) + " N*s/m)")
      << "\n";
    const auto& n = names[d];
    s << "plot " << n[0] << " using 1:2 with points pt 7 ps 1.1 lc rgb '#009e73' title "
      << "'direct, stable', " << n[1] << " using 1:2 with points pt 6 ps 1.1 lc rgb '#d55e00' "
      << "title 'direct, unstable', " << n[2]
      << " using 1:2 with points pt 5 ps 0.7 lc rgb '#0072b2' title 'coupled, stable (just "
         "above)', "
      << n[3] << " using 1:2 with points pt 4 ps 0.9 lc rgb '#cc79a7' title 'coupled, unstable', ";
    if (b - std::abs(B) > 0.0) {
      s << ShortestDecimal(2.0 * (b - std::abs(B))) << " * t, t with lines lw 1.5 lc rgb "
        << "'#000000' title 'bound K = 2 (b - |B|) / T'\n";
    } else {
      s << "NaN, NaN with lines lc rgb '#000000' title 'no bound: |B| >= b'\n";
    }
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace

void RenderStabilityMap(const std::vector<StabilityMapRow>& rows, double device_damping,
                        const std::string& title, const std::vector<plot::OutputFile>& outputs) {
  if (rows.empty()) throw std::invalid_argument("stability chart: no rows");
  if (outputs.empty()) throw std::invalid_argument("stability chart: no output file");
  int height = 0;
  const std::string body = Body(rows, device_damping, title, &height);
  const plot::TempDir work;
  plot::RenderScript(body, 1100, height, outputs, work);
}

}  // namespace fitfeel
