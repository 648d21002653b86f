#include "framework/plot/render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "framework/core/number_text.h"
#include "framework/plot/palette.h"

namespace fitfeel::plot {
namespace fs = std::filesystem;

namespace {

// Pixel sizes chosen so that a 12-point Sans face stays legible when the PNG is shown at its
// natural size on a laptop screen or embedded at page width in a README.
constexpr int kWidth = 1100;
constexpr int kLinePanelHeight = 400;
constexpr int kHeatPanelHeight = 330;
constexpr int kTitleHeight = 70;
constexpr double kLogDecades = 5.0;

std::string Rgb(unsigned rgb) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "'#%06x'", rgb & 0xffffffu);
  return buffer;
}

// A gnuplot string expression for several lines of text.
std::string QuoteLines(const std::vector<std::string>& lines) {
  std::string expression;
  for (const auto& line : lines) {
    if (!expression.empty()) expression += " . \"\\n\" . ";
    expression += QuoteForGnuplot(line);
  }
  return expression.empty() ? "''" : expression;
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

std::string ReadPrefix(const fs::path& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string prefix(bytes, '\0');
  in.read(prefix.data(), static_cast<std::streamsize>(bytes));
  prefix.resize(static_cast<std::size_t>(in.gcount()));
  return prefix;
}

bool LooksLikeImage(const fs::path& path, ImageFormat format) {
  std::error_code ec;
  if (fs::file_size(path, ec) == 0 || ec) return false;
  if (format == ImageFormat::kPng) return ReadPrefix(path, 8) == "\x89PNG\r\n\x1a\n";
  return ReadPrefix(path, 4096).find("<svg") != std::string::npos;
}

std::string Terminal(ImageFormat format, int width, int height) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height);
  // noenhanced: labels carry user text (scenario names with '_' or '^') that must print as is.
  if (format == ImageFormat::kPng) {
    return "set terminal pngcairo" + size + " font 'Sans,12' noenhanced background rgb 'white'\n";
  }
  return "set terminal svg" + size + " font 'Sans,12' noenhanced background rgb 'white'\n";
}

// Renders `body` into every output at the charts' width.
void RenderBody(const std::string& body, int height, const std::vector<OutputFile>& outputs,
                const TempDir& work) {
  RenderScript(body, kWidth, height, outputs, work);
}

std::string PaletteCommand() {
  std::string command = "set palette defined (";
  for (std::size_t k = 0; k < kViridis.size(); ++k) {
    if (k != 0) command += ", ";
    command += std::to_string(k) + " " + Rgb(kViridis[k]);
  }
  return command + ")\n";
}

bool EvenlySpaced(const Eigen::VectorXd& v) {
  if (v.size() < 2) return false;
  const double step = (v(v.size() - 1) - v(0)) / static_cast<double>(v.size() - 1);
  for (Eigen::Index k = 1; k < v.size(); ++k) {
    if (std::abs(v(k) - v(k - 1) - step) > 1e-6 * std::abs(step)) return false;
  }
  return true;
}

// Lower and upper edge of each cell whose centres are `v` (midpoints between centres).
void CellEdges(const Eigen::VectorXd& v, Eigen::VectorXd* lower, Eigen::VectorXd* upper) {
  const Eigen::Index n = v.size();
  lower->resize(n);
  upper->resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    (*lower)(k) = k > 0 ? 0.5 * (v(k - 1) + v(k)) : v(0) - 0.5 * (v(1) - v(0));
    (*upper)(k) = k + 1 < n ? 0.5 * (v(k) + v(k + 1)) : v(n - 1) + 0.5 * (v(n - 1) - v(n - 2));
  }
}

void CheckIncreasing(const Eigen::VectorXd& v, const char* what) {
  if (v.size() < 2) throw std::invalid_argument(std::string("heat map needs two or more ") + what);
  for (Eigen::Index k = 0; k < v.size(); ++k) {
    if (!std::isfinite(v(k)) || (k > 0 && !(v(k) > v(k - 1)))) {
      throw std::invalid_argument(std::string("heat map ") + what +
                                  " must be finite and strictly increasing");
    }
  }
}

// About five to ten round values (1, 2 or 5 times a power of ten apart) within [low, high].
std::vector<double> NiceTics(double low, double high) {
  const double span = high - low;
  const double power = std::pow(10.0, std::floor(std::log10(span / 5.0)));
  double step = power;
  for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
    step = factor * power;
    if (span / step <= 10.0) break;
  }
  std::vector<double> tics;
  // Multiples of the step counted, not summed: a running sum drifts (0.1 * 3 =
  // 0.30000000000000004).
  for (double k = std::ceil(low / step - 1e-9); k * step <= high + 1e-9 * span; k += 1.0) {
    tics.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
  }
  return tics;
}

// A colour-bar tic's label: the round value without binary noise (0.3, not 0.30000000000000004).
std::string TicLabel(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value + 0.0);
  return buffer;
}

}  // namespace

void RenderScript(const std::string& body, int width, int height,
                  const std::vector<OutputFile>& outputs, const TempDir& work) {
  if (outputs.empty()) throw std::invalid_argument("no output file to render into");
  const Gnuplot gnuplot = Gnuplot::Find();
  WriteText(work.path() / "chart.gp", body);
  std::string main = "set encoding utf8\n";
  std::vector<fs::path> images;
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const std::string name =
        "image" + std::to_string(k) + std::string(Extension(outputs[k].format));
    images.push_back(work.path() / name);
    main += Terminal(outputs[k].format, width, height);
    main += "set output '" + name + "'\nload 'chart.gp'\nunset output\n";
  }
  WriteText(work.path() / "main.gp", main);
  gnuplot.Run(work.path() / "main.gp", work.path());
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    if (!LooksLikeImage(images[k], outputs[k].format)) {
      throw std::runtime_error("gnuplot wrote no valid " +
                               std::string(Extension(outputs[k].format)) + " image");
    }
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) InstallAtomically(images[k], outputs[k].path);
}

void Render(const LineChart& chart, const std::vector<OutputFile>& outputs) {
  if (chart.panels.empty()) throw std::invalid_argument("line chart has no panel");
  double x_min = std::numeric_limits<double>::infinity();
  double x_max = -x_min;
  for (const auto& panel : chart.panels) {
    if (panel.series.empty()) throw std::invalid_argument("line panel has no series");
    for (const auto& series : panel.series) {
      if (series.x.size() != series.y.size()) {
        throw std::invalid_argument("series '" + series.label + "' has x and y of different size");
      }
      // A series that is zero throughout (a run in clearance) has finite points but none a log
      // axis can show: it keeps its place on the depth axis and in the key.
      bool any = false;
      for (std::size_t k = 0; k < series.x.size(); ++k) {
        if (std::isfinite(series.x[k]) && std::isfinite(series.y[k])) {
          any = true;
          x_min = std::min(x_min, series.x[k]);
          x_max = std::max(x_max, series.x[k]);
        }
      }
      if (!any) throw std::invalid_argument("series '" + series.label + "' has no finite point");
    }
  }
  if (x_max - x_min <= 0.0) {
    x_min -= 0.5;
    x_max += 0.5;
  }

  TempDir work;
  const int panels = static_cast<int>(chart.panels.size());
  std::ostringstream body;
  body << "reset\nset encoding utf8\n";
  body << "set multiplot layout " << panels << ",1 title " << QuoteForGnuplot(chart.title)
       << " font ',15'\n";
  // Equal margins so that the panels' depth axes line up.
  body << "set lmargin 12\nset rmargin 4\n";
  body << "set grid xtics ytics lc rgb '#c8c8c8' lw 1 dt solid\n";
  body << "set key below left Left reverse samplen 5 spacing 1.3 width 2\n";
  body << "set xrange [" << ShortestDecimal(x_min) << ":" << ShortestDecimal(x_max) << "]\n";
  for (int p = 0; p < panels; ++p) {
    const LinePanel& panel = chart.panels[static_cast<std::size_t>(p)];
    body << "set title " << QuoteForGnuplot(panel.title) << " font ',13'\n";
    body << "set xlabel " << QuoteForGnuplot(panel.x_label) << "\n";
    body << "set ylabel " << QuoteForGnuplot(panel.y_label) << "\n";
    // gnuplot warns about (and we refuse) an empty autoscaled range, so a flat panel gets an
    // explicit one around its value.
    double y_low = std::numeric_limits<double>::infinity(), y_high = -y_low;
    for (const auto& series : panel.series) {
      for (std::size_t k = 0; k < series.y.size(); ++k) {
        const double y = series.y[k];
        if (std::isfinite(series.x[k]) && std::isfinite(y) && (!panel.log_y || y > 0.0)) {
          y_low = std::min(y_low, y);
          y_high = std::max(y_high, y);
        }
      }
    }
    const bool flat = y_high - y_low <= 1e-9 * std::max(std::abs(y_high), 1e-300);
    const bool empty = !(y_high >= y_low);  // a log panel of series that are zero throughout
    body << "set ytics autofreq\n";
    if (panel.log_y) {
      body << "set logscale y\n";
      if (empty) {
        body << "set yrange [1:10]\n";
      } else if (flat) {
        body << "set yrange [" << ShortestDecimal(y_low / 2.0) << ":"
             << ShortestDecimal(y_high * 2.0) << "]\n";
      } else {
        // Near-zero values (a contact just closing) would stretch a log axis over ten decades
        // and squash everything a reader looks at; the axis keeps kLogDecades below the peak.
        // The lowest curve is lifted off the frame (a factor 1.5, a sixth of a decade), where a
        // constant one would otherwise hide in the border.
        const double bottom = std::max(y_low, y_high * std::pow(10.0, -kLogDecades)) / 1.5;
        body << "set yrange [" << ShortestDecimal(bottom) << ":*]\n";
        // Within two decades gnuplot labels at most one power of ten, which leaves the reader
        // without a scale: label the 1-2-5 steps instead.
        if (y_high < 100.0 * bottom) {
          body << "set ytics (";
          bool first = true;
          for (double decade = std::pow(10.0, std::floor(std::log10(bottom)));
               decade <= 10.0 * y_high; decade *= 10.0) {
            for (double step : {1.0, 2.0, 5.0}) {
              body << (first ? "" : ", ") << ShortestDecimal(step * decade);
              first = false;
            }
          }
          body << ")\n";
        }
      }
    } else {
      body << "unset logscale y\n";
      const double pad = y_high == 0.0 ? 1.0 : 0.1 * std::abs(y_high);
      if (panel.y_from_zero) {
        body << "set yrange [0:" << (y_high > 0.0 ? "*" : ShortestDecimal(pad)) << "]\n";
      } else if (flat) {
        body << "set yrange [" << ShortestDecimal(y_low - pad) << ":"
             << ShortestDecimal(y_high + pad) << "]\n";
      } else {
        body << "set yrange [*:*]\n";
      }
    }
    body << "plot ";
    // gnuplot cannot plot key entries alone; an undefined function gives the plot its axes.
    if (empty) body << "1/0 notitle, \\\n     ";
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const Series& series = panel.series[s];
      const std::string style = "lw 2.5 lc rgb " + Rgb(kLineColours[s % kLineColours.size()]) +
                                " dt " + std::to_string((s % 5) + 1);
      bool drawable = false;
      for (std::size_t k = 0; k < series.x.size(); ++k) {
        drawable = drawable || (std::isfinite(series.x[k]) && std::isfinite(series.y[k]) &&
                                (!panel.log_y || series.y[k] > 0.0));
      }
      if (!drawable) {
        if (s != 0) body << ", \\\n     ";
        body << "keyentry with lines " << style << " title "
             << QuoteForGnuplot(series.label + " (all 0)");
        continue;
      }
      const std::string name = "line" + std::to_string(p) + "_" + std::to_string(s) + ".dat";
      std::string data;
      data.reserve(series.x.size() * 24);
      for (std::size_t k = 0; k < series.x.size(); ++k) {
        // A blank line breaks the curve at a missing point (or a zero on a log axis) instead of
        // bridging it.
        if (std::isfinite(series.x[k]) && std::isfinite(series.y[k]) &&
            (!panel.log_y || series.y[k] > 0.0)) {
          data += ShortestDecimal(series.x[k]) + " " + ShortestDecimal(series.y[k]) + "\n";
        } else {
          data += "\n";
        }
      }
      WriteText(work.path() / name, data);
      if (s != 0) body << ", \\\n     ";
      body << "'" << name << "' using 1:2 with lines " << style << " title "
           << QuoteForGnuplot(series.label);
    }
    body << "\n";
  }
  body << "unset multiplot\n";
  const int height = kTitleHeight + 20 + panels * kLinePanelHeight +
                     panels * 30 * static_cast<int>(chart.panels.front().series.size());
  RenderBody(body.str(), height, outputs, work);
}

void Render(const HeatMapChart& chart, const std::vector<OutputFile>& outputs) {
  if (chart.panels.empty()) throw std::invalid_argument("heat map chart has no panel");
  for (const auto& map : chart.panels) {
    CheckIncreasing(map.x, "x positions");
    CheckIncreasing(map.y, "y positions");
    if (map.values.rows() != map.x.size() || map.values.cols() != map.y.size()) {
      throw std::invalid_argument("heat map '" + map.title + "' values are not x by y");
    }
    if (!map.values.allFinite()) {
      throw std::invalid_argument("heat map '" + map.title + "' has non-finite values");
    }
  }

  TempDir work;
  const int panels = static_cast<int>(chart.panels.size());
  std::vector<std::string> title_lines = {chart.title};
  title_lines.insert(title_lines.end(), chart.subtitle.begin(), chart.subtitle.end());
  std::ostringstream body;
  body << "reset\nset encoding utf8\n" << PaletteCommand();
  body << "set style textbox opaque fillcolor rgb 'white' noborder margins 2,1\n";
  body << "set multiplot layout " << panels << ",1 title " << QuoteLines(title_lines)
       << " font ',14'\n";
  // The right margin holds the colour bar, its longest tic label and the colour-bar label.
  std::size_t longest_mark = 6;
  for (const auto& map : chart.panels) {
    for (const auto& mark : map.colour_marks)
      longest_mark = std::max(longest_mark, mark.label.size());
  }
  body << "set lmargin 12\nset rmargin " << longest_mark + 6 << "\nset tics out\n";
  for (int p = 0; p < panels; ++p) {
    const HeatMap& map = chart.panels[static_cast<std::size_t>(p)];
    Eigen::VectorXd x_lower, x_upper, y_lower, y_upper;
    CellEdges(map.x, &x_lower, &x_upper);
    CellEdges(map.y, &y_lower, &y_upper);
    double low = map.values.minCoeff();
    double high = map.values.maxCoeff();
    if (map.colour_min) low = std::min(low, *map.colour_min);
    if (map.colour_max) high = std::max(high, *map.colour_max);
    if (!(high > low)) {
      const double pad = low == 0.0 ? 1.0 : 0.05 * std::abs(low);
      if (map.colour_min && !map.colour_max) {
        high = low + pad;
      } else {
        low -= pad;
        high += pad;
      }
    }
    body << "set title " << QuoteForGnuplot(map.title) << " font ',13'\n";
    body << "set xlabel " << QuoteForGnuplot(map.x_label) << "\n";
    body << "set ylabel " << QuoteForGnuplot(map.y_label) << "\n";
    // gnuplot spaces the label from the tic labels without counting the outward tic marks, and
    // two-digit labels then touch it: the offset moves it clear (the right margin has room).
    body << "set cblabel " << QuoteForGnuplot(map.colour_label) << " offset 1.5,0\n";
    body << "set xrange [" << ShortestDecimal(x_lower(0)) << ":"
         << ShortestDecimal(x_upper(x_upper.size() - 1)) << "]\n";
    body << "set yrange [" << ShortestDecimal(y_lower(0)) << ":"
         << ShortestDecimal(y_upper(y_upper.size() - 1)) << "]\n";
    body << "set cbrange [" << ShortestDecimal(low) << ":" << ShortestDecimal(high) << "]\n";
    if (map.y_tic_step > 0.0) {
      body << "set ytics " << ShortestDecimal(map.y_tic_step) << "\n";
    } else {
      body << "set ytics autofreq\n";
    }
    // Round-number tics, minus those that would print over a labelled mark.
    body << "set cbtics (";
    bool first = true;
    for (const double tic : NiceTics(low, high)) {
      bool near_mark = false;
      for (const auto& mark : map.colour_marks) {
        near_mark = near_mark || std::abs(tic - mark.value) < 0.09 * (high - low);
      }
      if (near_mark) continue;
      body << (first ? "" : ", ") << "'" << TicLabel(tic) << "' " << ShortestDecimal(tic);
      first = false;
    }
    for (const auto& mark : map.colour_marks) {
      body << (first ? "" : ", ") << QuoteForGnuplot(mark.label) << " "
           << ShortestDecimal(mark.value);
      first = false;
    }
    body << ")\n";
    body << "unset arrow\nunset label\n";
    for (std::size_t k = 0; k < map.y_lines.size(); ++k) {
      // Black under white dashes: visible on the dark and the light end of the colour map alike.
      const std::string y = ShortestDecimal(map.y_lines[k].value);
      body << "set arrow from graph 0, first " << y << " to graph 1, first " << y
           << " nohead front lw 4 lc rgb 'black'\n";
      body << "set arrow from graph 0, first " << y << " to graph 1, first " << y
           << " nohead front lw 2 dt 2 lc rgb 'white'\n";
      body << "set label " << QuoteForGnuplot(map.y_lines[k].label) << " at graph 0.01, first " << y
           << " offset 0,0.8 front textcolor rgb 'black' boxed\n";
    }
    const std::string name = "map" + std::to_string(p) + ".dat";
    std::string data;
    data.reserve(static_cast<std::size_t>(map.values.size()) * 40);
    const bool regular = EvenlySpaced(map.x) && EvenlySpaced(map.y);
    for (Eigen::Index i = 0; i < map.x.size(); ++i) {
      for (Eigen::Index j = 0; j < map.y.size(); ++j) {
        data += ShortestDecimal(map.x(i)) + " " + ShortestDecimal(map.y(j)) + " ";
        if (!regular) {
          data += ShortestDecimal(0.5 * (x_upper(i) - x_lower(i))) + " " +
                  ShortestDecimal(0.5 * (y_upper(j) - y_lower(j))) + " ";
        }
        data += ShortestDecimal(map.values(i, j)) + "\n";
      }
      data += "\n";
    }
    WriteText(work.path() / name, data);
    if (regular) {
      body << "plot '" << name << "' using 1:2:3 with image notitle\n";
    } else {
      // Cells of uneven size: one filled box per cell, its half-widths in columns 3 and 4.
      body << "plot '" << name
           << "' using 1:2:3:4:5 with boxxyerror fill solid 1.0 noborder lc palette notitle\n";
    }
  }
  body << "unset multiplot\n";
  // A lone map gets more height: it is the whole picture, not one of a stack.
  const int height = kTitleHeight + 22 * static_cast<int>(chart.subtitle.size()) +
                     (panels == 1 ? 440 : panels * kHeatPanelHeight);
  RenderBody(body.str(), height, outputs, work);
}

}  // namespace fitfeel::plot
