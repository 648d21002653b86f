#pragma once

#include <string>
#include <string_view>

#include "framework/core/export.h"

namespace fitfeel::iso965 {

// An ISO metric screw thread size, "M10x1.5" or "M10" (the coarse pitch of ISO 261 implied).
// Lengths in metres.
struct ThreadSize {
  double nominal = 0.0;  // d = D
  double pitch = 0.0;    // P
  bool coarse = false;   // P is the coarse pitch of the nominal diameter
  std::string text;      // normalised, pitch always written: "M10x1.5"
};

// An ISO 965-1 thread designation: size and tolerance class, "M10x1.5 6g", "M10 6H",
// "M10x1.25-6H", "M10x1.5 5g6g". A class of two parts gives the pitch diameter's grade and
// position, then the crest diameter's; a single part ("6g") applies to both.
struct ThreadDesignation {
  ThreadSize size;
  bool internal = false;  // upper-case position: G, H (nut); lower case: e, f, g, h (bolt)
  char position = 'h';
  int pitch_grade = 6;
  int crest_grade = 6;
  std::string pitch_diameter_class;  // "5g"
  std::string crest_diameter_class;  // "6g"
  std::string tolerance_class;       // as written in the designation, "5g6g" or "6g"
  std::string text;                  // normalised: "M10x1.5 5g6g"
};

// Limits of one diameter, in metres. A side the standard leaves open (the bolt's minor diameter
// below, the nut's major diameter above) has an infinite deviation.
struct DiameterLimits {
  double basic = 0.0;
  double lower_deviation = 0.0;
  double upper_deviation = 0.0;
  double min() const { return basic + lower_deviation; }
  double max() const { return basic + upper_deviation; }
};

// The limits of an ISO 965-1 tolerance class on an ISO 68-1 basic profile, in metres.
// Bolt: major (d) from es - Td to es, pitch (d2) from es - Td2 to es, minor d3 up to d3 + es.
// Nut: major (D) from EI up, pitch (D2) from EI to EI + TD2, minor (D1) from EI to EI + TD1.
struct ThreadLimits {
  ThreadDesignation designation;
  double fundamental_deviation = 0.0;  // es (bolt) or EI (nut)
  double pitch_tolerance = 0.0;        // Td2 or TD2
  double crest_tolerance = 0.0;        // Td (bolt major) or TD1 (nut minor)
  DiameterLimits major;
  DiameterLimits pitch_diameter;
  DiameterLimits minor;         // bolt: d3 (rounded root); nut: D1
  double flat_minor_max = 0.0;  // bolt only: d1 + es, the minor diameter of a flat root
  double range_lower = 0.0;     // ISO 965-1 diameter range of Td2/TD2: lower < d <= upper
  double range_upper = 0.0;
};

// ISO 68-1 basic profile of a 60 degree thread: fundamental triangle height H and the basic
// pitch (d2 = D2), minor (d1 = D1) and root (d3) diameters from d and P, in metres.
FITFEEL_API double FundamentalTriangleHeight(double pitch);
FITFEEL_API double BasicPitchDiameter(double nominal, double pitch);
FITFEEL_API double BasicMinorDiameter(double nominal, double pitch);
FITFEEL_API double BasicRootDiameter(double nominal, double pitch);

// True when `text` starts like a metric thread ('M' and a digit), so that callers accepting
// other sizes as well can tell which grammar to apply.
FITFEEL_API bool LooksLikeThread(std::string_view text);

// Throw UserError naming what was expected and found: not of the form M<d>[x<P>], a nominal
// diameter outside M3 to M36 or not in ISO 261, a pitch ISO 261 does not give for it (the
// message lists those it does).
FITFEEL_API ThreadSize ParseThreadSize(std::string_view text);

// As ParseThreadSize, and for the class: an unknown position letter, a grade outside the
// standard's range for that diameter and thread, two parts with different positions.
FITFEEL_API ThreadDesignation ParseDesignation(std::string_view text);

// Throws UserError for a class ISO 965-1 does not tabulate at that pitch (position e below
// 0.5 mm, the coarsest grades at fine pitches).
FITFEEL_API ThreadLimits Lookup(const ThreadDesignation& designation);

}  // namespace fitfeel::iso965
