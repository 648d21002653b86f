#include "framework/stability/stability_map.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include "framework/core/error.h"
#include "framework/core/os_reason.h"
#include "framework/core/path_check.h"
#include "framework/core/temporary_files.h"

namespace fitfeel {

std::vector<StabilityMapRow> SweepStabilityMap(const StabilityMapSettings& s) {
  if (s.methods.empty() || s.rates.empty() || s.stiffnesses.empty() || s.dampings.empty()) {
    throw UserError(
        "stability map: every axis (methods, rates, stiffnesses, dampings) needs a value");
  }
  std::vector<StabilityMapRow> rows;
  rows.reserve(s.methods.size() * s.rates.size() * s.stiffnesses.size() * s.dampings.size());
  WallExperiment e = s.base;
  for (RenderingMethod method : s.methods) {
    for (double rate : s.rates) {
      for (double damping : s.dampings) {
        for (double stiffness : s.stiffnesses) {
          e.method = method;
          e.rate = rate;
          e.damping = damping;
          e.stiffness = stiffness;
          StabilityMapRow row;
          row.method = method;
          row.rate = rate;
          row.stiffness = stiffness;
          row.damping = damping;
          row.outcome = RunWallExperiment(e);
          rows.push_back(row);
        }
      }
    }
  }
  return rows;
}

std::vector<double> LogSpaced(double low, double high, int count_per_decade) {
  if (!(low > 0.0) || !(high >= low) || !std::isfinite(high) || count_per_decade < 1 ||
      count_per_decade > 1000) {
    throw UserError(
        "stability map: a log-spaced range needs 0 < low <= high and 1..1000 points "
        "per decade");
  }
  if (high == low) return {low};
  std::vector<double> out;
  const double decades = std::log10(high / low);
  const int intervals = std::max(1, static_cast<int>(std::ceil(decades * count_per_decade - 1e-9)));
  for (int i = 0; i <= intervals; ++i) {
    out.push_back(i == intervals ? high : low * std::pow(10.0, decades * i / intervals));
  }
  return out;
}

std::string StabilityMapCsv(const std::vector<StabilityMapRow>& rows) {
  std::ostringstream out;
  out << "method,rate_Hz,stiffness_N_per_m,damping_Ns_per_m,bound_ok,stable,energy_growth_J,"
         "peak_force_N\n";
  out.precision(10);
  for (const StabilityMapRow& r : rows) {
    out << ToString(r.method) << ',' << r.rate << ',' << r.stiffness << ',' << r.damping << ','
        << (r.outcome.bound_ok ? 1 : 0) << ',' << (r.outcome.stable ? 1 : 0) << ','
        << r.outcome.energy_growth << ',' << r.outcome.peak_force << '\n';
  }
  return out.str();
}

void WriteFileAtomically(const std::filesystem::path& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (const std::string why = WhyNotFolder(folder); !why.empty()) {
    throw UserError("cannot write '" + path.string() + "': folder '" + folder.string() + "' " +
                    why);
  }
  if (fs::is_directory(path, ec)) {
    throw UserError("cannot write '" + path.string() + "': it is a folder");
  }
  const fs::path temporary = TemporaryPathFor(path);
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    const int write_error = errno;
    if (!out) {
      fs::remove(temporary, ec);
      throw UserError("cannot write '" + temporary.string() + "': " + OsReason(write_error));
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw UserError("cannot replace '" + path.string() + "': " + ec.message());
  }
}

}  // namespace fitfeel
