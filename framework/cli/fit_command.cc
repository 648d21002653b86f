#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/iso286/fit.h"
#include "framework/iso286/iso286.h"
#include "framework/iso965/fit.h"

namespace fitfeel::cli {
namespace {

// "20", "20 mm", "20mm", "0.02 m", "20000 um": a bare number is millimetres, as on drawings.
double ParseNominalSize(std::string_view text) {
  const std::string shown(text);
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end == text.data()) {
    throw UserError(
        "fit: the nominal size must be a number with an optional length unit (e.g. "
        "20 or \"20 mm\"), found '" +
        shown + "'");
  }
  std::string_view unit(end, static_cast<std::size_t>(text.data() + text.size() - end));
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  double metres_per_unit = 0.0;
  if (unit.empty() || unit == "mm") {
    metres_per_unit = 1e-3;
  } else if (unit == "m") {
    metres_per_unit = 1.0;
  } else if (unit == "cm") {
    metres_per_unit = 1e-2;
  } else if (unit == "um" || unit == "\u00b5m") {
    metres_per_unit = 1e-6;
  } else {
    throw UserError("fit: unknown length unit '" + std::string(unit) + "' in '" + shown +
                    "' (accepted: mm, cm, m, um; a bare number is mm)");
  }
  if (!std::isfinite(value)) {
    throw UserError("fit: the nominal size must be finite, found '" + shown + "'");
  }
  return value * metres_per_unit;
}

// Fixed notation with at most `max_decimals`, trailing zeros removed down to `min_decimals`.
std::string Fixed(double value, int min_decimals, int max_decimals, bool sign) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, sign ? "%+.*f" : "%.*f", max_decimals, value);
  std::string text(buffer);
  const std::size_t dot = text.find('.');
  if (dot != std::string::npos) {
    std::size_t keep = text.size();
    while (keep > dot + 1 + static_cast<std::size_t>(min_decimals) && text[keep - 1] == '0') {
      --keep;
    }
    if (keep == dot + 1) --keep;
    text.resize(keep);
  }
  if (text == "+0" || text == "-0") text = "0";
  return text;
}

std::string Um(double metres, bool sign = true) { return Fixed(metres * 1e6, 0, 2, sign) + " um"; }

std::string Mm(double metres) { return Fixed(metres * 1e3, 3, 5, false) + " mm"; }

// Thread limits to the micrometre, as ISO 965-2 prints them (the basic diameters of ISO 724 are
// rounded so).
std::string ThreadMm(double metres) { return Fixed(metres * 1e3, 3, 3, false) + " mm"; }

std::string PadLeft(std::string text, std::size_t width) {
  if (text.size() < width) text.insert(0, width - text.size(), ' ');
  return text;
}

void PrintPart(std::ostream& out, const char* role, const iso286::Limits& part) {
  const char* lower_name = part.is_hole ? "EI" : "ei";
  const char* upper_name = part.is_hole ? "ES" : "es";
  out << "  " << role << " " << part.code
      << std::string(6 - std::min<std::size_t>(5, part.code.size()), ' ') << lower_name << " = "
      << PadLeft(Um(part.lower_deviation), 10) << "   " << upper_name << " = "
      << PadLeft(Um(part.upper_deviation), 10) << "   limits "
      << Mm(part.nominal + part.lower_deviation) << " .. "
      << Mm(part.nominal + part.upper_deviation) << "   (tolerance "
      << Um(part.upper_deviation - part.lower_deviation, false) << ")\n";
}

// One diameter of a thread, in the columns of PrintPart; `upper` false where the standard sets
// only the lower limit (D), `lower` false where only the upper (d3).
void PrintDiameter(std::ostream& out, const char* name, bool internal,
                   const iso965::DiameterLimits& limits, bool lower, bool upper) {
  const char* lower_name = internal ? "EI" : "ei";
  const char* upper_name = internal ? "ES" : "es";
  out << "        " << name << std::string(4 - std::string_view(name).size(), ' ');
  out << (lower ? std::string(lower_name) + " = " + PadLeft(Um(limits.lower_deviation), 10)
                : std::string(15, ' '))
      << "   "
      << (upper ? std::string(upper_name) + " = " + PadLeft(Um(limits.upper_deviation), 10)
                : std::string(15, ' '));
  if (lower && upper) {
    out << "   limits " << ThreadMm(limits.min()) << " .. " << ThreadMm(limits.max())
        << "   (tolerance " << Um(limits.upper_deviation - limits.lower_deviation, false) << ")\n";
  } else {
    out << "   " << (lower ? "min " + ThreadMm(limits.min()) : "max " + ThreadMm(limits.max()))
        << "\n";
  }
}

void PrintThread(std::ostream& out, const char* role, const iso965::ThreadLimits& part) {
  const bool internal = part.designation.internal;
  out << "  " << role << " " << part.designation.tolerance_class << "\n";
  if (internal) {
    PrintDiameter(out, "D1", true, part.minor, true, true);
    PrintDiameter(out, "D2", true, part.pitch_diameter, true, true);
    PrintDiameter(out, "D", true, part.major, true, false);
  } else {
    PrintDiameter(out, "d", false, part.major, true, true);
    PrintDiameter(out, "d2", false, part.pitch_diameter, true, true);
    PrintDiameter(out, "d3", false, part.minor, false, true);
  }
}

// `fitfeel fit M10x1.5 6H/6g`: ISO 965-1 limits of nut and bolt and what their pitch diameters
// leave free.
void RunThreadFit(const std::string& size, const std::string& code) {
  iso965::ThreadFit fit;
  try {
    fit = iso965::LookupFit(size, code);
  } catch (const UserError& e) {
    throw UserError(std::string("fit: ") + e.what());
  }
  const iso965::ThreadSize& thread = fit.bolt.designation.size;
  constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
  std::ostream& out = std::cout;
  out << "ISO 965-1 thread fit " << thread.text << " " << fit.nut.designation.tolerance_class << "/"
      << fit.bolt.designation.tolerance_class << "  (" << (thread.coarse ? "coarse" : "fine")
      << " pitch " << Fixed(thread.pitch * 1e3, 0, 3, false) << " mm, d2 range "
      << Fixed(fit.bolt.range_lower * 1e3, 0, 1, false) << "-"
      << Fixed(fit.bolt.range_upper * 1e3, 0, 1, false) << " mm)\n";
  PrintThread(out, "nut ", fit.nut);
  PrintThread(out, "bolt", fit.bolt);
  out << "  pitch-diameter clearance (D2 - d2): min " << Um(fit.min_clearance) << ", max "
      << Um(fit.max_clearance) << "\n";
  out << "  axial play (clearance x tan 30 deg): min " << Um(fit.min_axial_play, false) << ", max "
      << Um(fit.max_axial_play, false) << "\n";
  out << "  angular backlash (2 pi play / P): min "
      << Fixed(fit.min_angular_backlash * kDegreesPerRadian, 0, 2, false) << " deg, max "
      << Fixed(fit.max_angular_backlash * kDegreesPerRadian, 0, 2, false) << " deg\n";
}

void RunFit(const std::vector<std::string>& args) {
  if (iso965::LooksLikeThread(args[0])) {
    std::string size = args[0];
    if (args.size() == 3) size += " " + args[1];
    RunThreadFit(size, args.back());
    return;
  }
  // `fitfeel fit 20 mm H7/g6` arrives as three words; `fitfeel fit "20 mm" H7/g6` as two.
  std::string size_text = args[0];
  if (args.size() == 3) size_text += " " + args[1];
  const std::string& code = args.back();
  const double nominal = ParseNominalSize(size_text);
  iso286::Fit fit;
  try {
    fit = iso286::LookupFit(nominal, code);
  } catch (const std::invalid_argument& e) {
    throw UserError(std::string("fit: ") + e.what());
  }
  std::ostream& out = std::cout;
  out << "ISO 286 fit " << Fixed(nominal * 1e3, 0, 4, false) << " mm " << fit.hole.code << "/"
      << fit.shaft.code << "  (size step " << Fixed(fit.hole.step_lower * 1e3, 0, 0, false) << "-"
      << Fixed(fit.hole.step_upper * 1e3, 0, 0, false) << " mm)\n";
  PrintPart(out, "hole ", fit.hole);
  PrintPart(out, "shaft", fit.shaft);
  out << "  clearance (hole - shaft; negative = interference): min " << Um(fit.min_clearance)
      << ", max " << Um(fit.max_clearance) << "\n";
  out << "  fit class: " << iso286::ToString(fit.fit_class) << "\n";
}

}  // namespace

void AddFitCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "fit",
      "Limits and fit class of an ISO 286 fit, e.g. `fitfeel fit 20 H7/g6` (size in mm "
      "unless it carries a unit: \"20 mm\", \"0.02 m\"), or of an ISO 965-1 thread fit, e.g. "
      "`fitfeel fit M10x1.5 6H/6g`, with its clearance, axial play and backlash");
  auto args = std::make_shared<std::vector<std::string>>();
  cmd->add_option("size_and_fit", *args, "e.g. 20 H7/g6 or \"20 mm\" H7/js6")
      ->option_text("<size> <HOLE/shaft>")
      ->required()
      ->expected(2, 3);
  cmd->callback([args] { RunFit(*args); });
}

}  // namespace fitfeel::cli
