#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace fitfeel::plot {

// Plain data for the charts: no file formats, no scene. Everything here is in the units the
// labels say (the builders convert from SI), so a renderer only draws.

// One curve: points (x[k], y[k]); non-finite points leave a gap.
struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
};

// One x-y panel. Panels of a chart share their x range so that they read as one figure.
struct LinePanel {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool y_from_zero = false;  // start the y axis at 0 (magnitudes)
  bool log_y = false;        // logarithmic y axis over at most 5 decades; points <= 0 left out
  std::vector<Series> series;
};

struct LineChart {
  std::string title;
  std::vector<LinePanel> panels;  // drawn top to bottom
};

// A labelled value on a colour bar (e.g. a tolerance limit) or an axis.
struct ColourMark {
  double value = 0.0;
  std::string label;
};

// A map of values(i, j) at (x[i], y[j]): x along the horizontal axis, y along the vertical one.
// x and y are cell centres; each must be strictly increasing.
struct HeatMap {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::string colour_label;
  Eigen::VectorXd x;
  Eigen::VectorXd y;
  Eigen::MatrixXd values;  // x.size() x y.size()
  // Colour range; widened to the data so that no value is drawn out of range. Unset: the data's.
  std::optional<double> colour_min;
  std::optional<double> colour_max;
  std::vector<ColourMark> colour_marks;
  // Labelled horizontal lines across the map at these y values (e.g. a force direction).
  std::vector<ColourMark> y_lines;
  double y_tic_step = 0.0;  // spacing of the y tics, 0 = gnuplot's choice (e.g. 90 for degrees)
};

struct HeatMapChart {
  std::string title;
  std::vector<std::string> subtitle;  // lines under the title (e.g. resultant forces)
  std::vector<HeatMap> panels;        // drawn top to bottom
};

}  // namespace fitfeel::plot
