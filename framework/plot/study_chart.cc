#include "framework/plot/study_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "framework/core/error.h"
#include "framework/plot/render.h"

namespace fitfeel::plot {
namespace {

// Quantile curve: sorted values over the plotting positions (k + 0.5) / n.
Series Quantiles(const std::string& label, std::vector<double> values) {
  std::sort(values.begin(), values.end());
  Series s;
  s.label = label;
  const double n = static_cast<double>(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    s.x.push_back((static_cast<double>(k) + 0.5) / n);
    s.y.push_back(values[k]);
  }
  return s;
}

// Logarithmic when the positive values span more than two decades.
bool SpansDecades(const std::vector<study::StudyRecord>& studies, bool maxima) {
  double lo = INFINITY, hi = 0.0;
  for (const auto& s : studies) {
    for (double v : maxima ? s.axial_max_N : s.axial_mean_N) {
      if (v > 0.0) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  }
  return hi > 0.0 && hi / lo > 100.0;
}

LinePanel Panel(const std::vector<study::StudyRecord>& studies,
                const std::optional<ReferenceLine>& reference, bool maxima) {
  LinePanel panel;
  panel.title = maxima ? "largest axial resistance of each pair's insertion"
                       : "mean axial resistance of each pair's insertion";
  panel.x_label = "fraction of part pairs at or below";
  panel.y_label = maxima ? "max axial resistance (N)" : "mean axial resistance (N)";
  panel.log_y = SpansDecades(studies, maxima);
  panel.y_from_zero = !panel.log_y;
  for (const auto& s : studies) {
    char text[160];
    std::snprintf(text, sizeof text, "%s (%zu pairs, P(interference) %.2f)", s.scenario.c_str(),
                  s.axial_mean_N.size(), s.probability_of_interference);
    panel.series.push_back(Quantiles(text, maxima ? s.axial_max_N : s.axial_mean_N));
  }
  if (reference) {
    panel.series.push_back(
        Series{reference->label, {0.0, 1.0}, {reference->value, reference->value}});
  }
  return panel;
}

}  // namespace

LineChart MakeStudyChart(const std::vector<study::StudyRecord>& studies,
                         const std::optional<ReferenceLine>& reference) {
  if (studies.empty()) throw UserError("plot study: no study folders");
  LineChart chart;
  chart.title = "Insertion force over part pairs";
  chart.panels.push_back(Panel(studies, reference, false));
  chart.panels.push_back(Panel(studies, reference, true));
  return chart;
}

void WriteStudyChart(const std::filesystem::path& dir) {
  Render(MakeStudyChart({study::LoadStudy(dir)}, std::nullopt), ResolveOutputs(dir / "study.png"));
}

}  // namespace fitfeel::plot
