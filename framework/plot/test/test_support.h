#pragma once

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "framework/plot/gnuplot.h"

namespace fitfeel::plot::testing {

// Tests that draw need gnuplot; `make test` installs it, so they are skipped only on a machine
// without it.
#define FITFEEL_REQUIRE_GNUPLOT()                                                        \
  do {                                                                                   \
    if (!::fitfeel::plot::Gnuplot::Locate()) GTEST_SKIP() << "gnuplot is not installed"; \
  } while (false)

// A fresh folder per test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() : dir_() {}
  const std::filesystem::path& path() const { return dir_.path(); }

 private:
  TempDir dir_;
};

inline void WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline bool IsPng(const std::filesystem::path& path) {
  const std::string bytes = ReadFile(path);
  return bytes.size() > 100 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

inline bool IsSvg(const std::filesystem::path& path) {
  const std::string bytes = ReadFile(path);
  return bytes.size() > 100 && bytes.find("<svg") != std::string::npos &&
         bytes.find("</svg>") != std::string::npos;
}

// Sets an environment variable for the scope of one test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_.c_str(), old_->c_str(), 1);
    } else {
      ::unsetenv(name_.c_str());
    }
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// A run folder following the output contract: a trace of `rows` ticks where the first ticks are
// positioning and the rest constrained, and a matching summary.
inline void WriteRun(const std::filesystem::path& dir, const std::string& scenario,
                     const std::string& law, double axial_scale, int rows = 200) {
  std::filesystem::create_directories(dir);
  std::string csv = "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us\n";
  for (int k = 0; k < rows; ++k) {
    const bool constrained = k >= 20;
    const double depth = constrained ? 0.1 * (k - 20) : 0.0;
    const double fy = constrained ? -axial_scale * (1.0 + 0.1 * std::sin(0.3 * k)) : 0.0;
    csv += std::to_string(0.001 * k) + "," + (constrained ? "constrained" : "positioning") + "," +
           std::to_string(depth) + ",0.5," + std::to_string(fy) + ",2.0,12\n";
  }
  WriteFile(dir / "trace.csv", csv);
  WriteFile(dir / "summary.json",
            "{\"scenario\": \"" + scenario + "\", \"law\": \"" + law +
                "\", \"seed\": 1, \"scenario_file\": \"scenarios/" + scenario +
                ".yaml\", \"ticks\": " + std::to_string(rows) +
                ", \"axial_resistance_N\": {\"mean\": " + std::to_string(axial_scale) +
                ", \"min\": " + std::to_string(0.9 * axial_scale) +
                ", \"max\": " + std::to_string(1.1 * axial_scale) +
                "}, \"radial_resistance_N\": {\"mean\": 2.06, \"min\": 2.06, \"max\": 2.06}}\n");
}

// A screw's run folder (a thread scene's): WriteRun's summary and a trace with the pose's columns
// and the screw's torque_Nm and preload_N. Its part turns 0.1 rad a tick; the torque is 0.01 N*m
// while it runs down (tick 100 on) and then rises 0.4 N*m a tick, the preload 1 kN per N*m.
// With `seated`, the trace's seated column (1 from row 100, where the preload starts).
inline void WriteScrewRun(const std::filesystem::path& dir, int rows = 200, bool seated = false) {
  WriteRun(dir, "bolt-m10", "flank", 5.0, rows);
  std::string csv =
      "t_s,stage,depth_mm,fx_N,fy_N,fz_N,x_mm,y_mm,z_mm,angle_rad,preload_N,torque_Nm" +
      std::string(seated ? ",seated\n" : "\n");
  for (int k = 0; k < rows; ++k) {
    const bool constrained = k >= 20;
    const double angle = constrained ? 0.1 * (k - 20) : 0.0;
    const double torque = !constrained ? 0.0 : k < 100 ? 0.01 : 0.01 + 0.4 * (k - 100);
    csv += std::to_string(0.001 * k) + "," + (constrained ? "constrained" : "positioning") + "," +
           std::to_string(1.5 * angle / (2 * M_PI)) + ",0,-5,0,0,0,0," + std::to_string(angle) +
           "," + std::to_string(k < 100 ? 0.0 : 1000.0 * torque) + "," + std::to_string(torque) +
           (seated ? (k < 100 ? ",0" : ",1") : "") + "\n";
  }
  WriteFile(dir / "trace.csv", csv);
}

}  // namespace fitfeel::plot::testing
