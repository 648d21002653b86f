#include "framework/iso965/iso965.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/iso965/tables.h"

namespace fitfeel::iso965 {
namespace {

namespace t = tables;

constexpr double kMetresPerMillimetre = 1e-3;
constexpr double kMetresPerMicrometre = 1e-6;
// Diameters and pitches are written in mm with at most three decimals; two values closer than
// this are the same entry.
constexpr double kSameMm = 1e-9;

// The R40 preferred numbers (ISO 3) from 25 um to 1000 um, below 100 um in their rounded R'40
// form, as ISO 965-1 prints its tolerances. Consecutive entries are one R40 step, a factor of
// 10^(1/40), apart.
constexpr std::array<int, 65> kR40Um = {
    25,  26,  28,  30,  32,  34,  36,  38,  40,  42,  45,  48,  50,  53,  56,  60,  63,
    67,  71,  75,  80,  85,  90,  95,  100, 106, 112, 118, 125, 132, 140, 150, 160, 170,
    180, 190, 200, 212, 224, 236, 250, 265, 280, 300, 315, 335, 355, 375, 400, 425, 450,
    475, 500, 530, 560, 600, 630, 670, 710, 750, 800, 850, 900, 950, 1000};

// The grade factors of ISO 965-1 are R40 numbers themselves, so the product of a tabulated
// grade-6 value and a factor is the R40 value that many steps along (0.63 = 8 steps down,
// 1.32 = 5 up). The published tables follow the steps, where multiplying the rounded numbers
// would not: TD2(6) = 1.32 x 132 um = 174 um, the table has 180 um, 5 steps above 132 um.
struct GradeSteps {
  int first_grade;
  std::array<int, 7> steps;  // from first_grade on; kNoGrade past the last
};
constexpr int kNoGrade = 1000;
constexpr GradeSteps kTd2Steps = {3, {-12, -8, -4, 0, 4, 8, 12}};             // 0.5 .. 2
constexpr GradeSteps kTD2Steps = {4, {-3, 1, 5, 9, 13, kNoGrade, kNoGrade}};  // 0.85 .. 2.12
constexpr GradeSteps kTd1Steps = {4, {-8, -4, 0, 4, 8, kNoGrade, kNoGrade}};  // 0.63 .. 1.6
constexpr GradeSteps kTdSteps = {4,
                                 {-8, kNoGrade, 0, kNoGrade, 8, kNoGrade, kNoGrade}};  // 0.63, 1.6

std::string Mm(double mm) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", mm);
  return buffer;
}

bool GradeDefined(const GradeSteps& steps, int grade) {
  const int i = grade - steps.first_grade;
  return i >= 0 && i < static_cast<int>(steps.steps.size()) && steps.steps[i] != kNoGrade;
}

std::string GradeList(const GradeSteps& steps) {
  std::string list;
  for (int i = 0; i < static_cast<int>(steps.steps.size()); ++i) {
    if (steps.steps[i] == kNoGrade) continue;
    list += (list.empty() ? "" : ", ") + std::to_string(steps.first_grade + i);
  }
  return list;
}

// The tolerance of `grade` in micrometres, from the tabulated grade-6 value.
double GradeValue(double grade6_um, const GradeSteps& steps, int grade) {
  int at = -1;
  for (int i = 0; i < static_cast<int>(kR40Um.size()); ++i) {
    if (kR40Um[i] == grade6_um) at = i;
  }
  const int to = at + steps.steps[grade - steps.first_grade];
  if (at < 0 || to < 0 || to >= static_cast<int>(kR40Um.size())) {
    // The tables and steps are fixed; only an edit of them can land here.
    throw std::logic_error("iso965: grade " + std::to_string(grade) + " of " + Mm(grade6_um) +
                           " um is outside the R40 series carried");
  }
  return kR40Um[to];
}

[[noreturn]] void Refuse(std::string_view shown, const std::string& why) {
  throw UserError("ISO thread '" + std::string(shown) + "': " + why);
}

std::string_view Trim(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  return text;
}

// A decimal number at the start of `text` (digits, at most one point); advances past it.
bool TakeNumber(std::string_view& text, double* value) {
  std::size_t n = 0;
  bool point = false;
  while (n < text.size() &&
         (std::isdigit(static_cast<unsigned char>(text[n])) || (text[n] == '.' && !point))) {
    point = point || text[n] == '.';
    ++n;
  }
  if (n == 0 || text[n - 1] == '.' || text[0] == '.') return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + n, *value);
  if (ec != std::errc() || end != text.data() + n) return false;
  text.remove_prefix(n);
  return true;
}

const t::DiameterPitches* FindDiameter(double nominal_mm) {
  for (const t::DiameterPitches& row : t::kDiameterPitches) {
    if (std::abs(row.nominal_mm - nominal_mm) < kSameMm) return &row;
  }
  return nullptr;
}

std::string DiameterList() {
  std::string list;
  for (const t::DiameterPitches& row : t::kDiameterPitches) {
    list += (list.empty() ? "M" : ", M") + Mm(row.nominal_mm);
  }
  return list;
}

std::string PitchList(const t::DiameterPitches& row) {
  std::string list = Mm(row.coarse_mm) + " (coarse)";
  for (double fine : row.fine_mm) {
    if (fine > 0.0) list += ", " + Mm(fine);
  }
  return list;
}

const t::PitchRow& FindPitchRow(double pitch_mm) {
  for (const t::PitchRow& row : t::kPitchRows) {
    if (std::abs(row.pitch_mm - pitch_mm) < kSameMm) return row;
  }
  throw std::logic_error("iso965: pitch " + Mm(pitch_mm) + " mm has no ISO 965-1 row");
}

int FindRange(double nominal_mm) {
  for (int i = 0; i < static_cast<int>(t::kRanges.size()); ++i) {
    if (nominal_mm > t::kRanges[i].lower_mm && nominal_mm <= t::kRanges[i].upper_mm + kSameMm) {
      return i;
    }
  }
  throw std::logic_error("iso965: M" + Mm(nominal_mm) + " is in no ISO 965-1 diameter range");
}

double Td2Grade6(int range, double pitch_mm) {
  for (const t::PitchTolerance& row : t::kTd2Grade6) {
    if (row.range == range && std::abs(row.pitch_mm - pitch_mm) < kSameMm) return row.td26_um;
  }
  throw std::logic_error("iso965: no Td2(6) for pitch " + Mm(pitch_mm) + " mm");
}

ThreadSize ParseSizeIn(std::string_view size, std::string_view shown) {
  std::string_view rest = size;
  if (rest.empty() || rest.front() != 'M') {
    Refuse(shown, "expected a size M<d> or M<d>x<P> (e.g. M10, M10x1.5), found '" +
                      std::string(size) + "'");
  }
  rest.remove_prefix(1);
  double nominal_mm = 0.0;
  if (!TakeNumber(rest, &nominal_mm)) {
    Refuse(shown, "expected the nominal diameter in mm after 'M' (e.g. M10), found '" +
                      std::string(size) + "'");
  }
  const t::DiameterPitches* row = FindDiameter(nominal_mm);
  if (row == nullptr) {
    Refuse(shown, "M" + Mm(nominal_mm) +
                      " is not an ISO 261 first or second choice diameter from M3 to M36 (" +
                      DiameterList() + ")");
  }
  double pitch_mm = row->coarse_mm;
  if (!rest.empty()) {
    if (rest.front() == 'x' || rest.front() == 'X') {
      rest.remove_prefix(1);
    } else if (rest.substr(0, 2) == "\u00d7") {
      rest.remove_prefix(2);
    } else {
      Refuse(shown, "expected 'x' and the pitch after M" + Mm(nominal_mm) + " (e.g. M" +
                        Mm(nominal_mm) + "x" + Mm(row->coarse_mm) + "), found '" +
                        std::string(rest) + "'");
    }
    if (!TakeNumber(rest, &pitch_mm) || !rest.empty()) {
      Refuse(shown, "expected the pitch in mm after 'x' (e.g. M" + Mm(nominal_mm) + "x" +
                        Mm(row->coarse_mm) + "), found '" + std::string(size) + "'");
    }
  }
  bool known = std::abs(pitch_mm - row->coarse_mm) < kSameMm;
  for (double fine : row->fine_mm)
    known = known || (fine > 0.0 && std::abs(pitch_mm - fine) < kSameMm);
  if (!known) {
    Refuse(shown, Mm(pitch_mm) + " mm is not an ISO 261 pitch of M" + Mm(nominal_mm) +
                      " (expected one of " + PitchList(*row) + ")");
  }
  ThreadSize parsed;
  parsed.nominal = nominal_mm * kMetresPerMillimetre;
  parsed.pitch = pitch_mm * kMetresPerMillimetre;
  parsed.coarse = std::abs(pitch_mm - row->coarse_mm) < kSameMm;
  parsed.text = "M" + Mm(nominal_mm) + "x" + Mm(pitch_mm);
  return parsed;
}

bool IsPositionLetter(char c) {
  return std::string_view("efghGH").find(c) != std::string_view::npos;
}

// One part of a class, "6g": grade digit, position letter.
void TakePart(std::string_view& text, std::string_view shown, const std::string& whole, int* grade,
              char* position) {
  if (text.size() < 2 || !std::isdigit(static_cast<unsigned char>(text[0])) ||
      !std::isalpha(static_cast<unsigned char>(text[1]))) {
    Refuse(shown, "expected a tolerance class such as 6g, 6H or 5g6g after the size, found '" +
                      whole + "'");
  }
  if (!IsPositionLetter(text[1])) {
    Refuse(shown,
           "expected a tolerance position e, f, g, h (external thread) or G, H (internal "
           "thread) in '" +
               whole + "', found '" + std::string(1, text[1]) + "'");
  }
  *grade = text[0] - '0';
  *position = text[1];
  text.remove_prefix(2);
}

void CheckGrade(std::string_view shown, int grade, bool internal, bool pitch) {
  const GradeSteps& steps =
      internal ? (pitch ? kTD2Steps : kTd1Steps) : (pitch ? kTd2Steps : kTdSteps);
  if (GradeDefined(steps, grade)) return;
  const char* what = internal ? (pitch ? "pitch diameter D2 of an internal thread"
                                       : "minor diameter D1 of an internal thread")
                              : (pitch ? "pitch diameter d2 of an external thread"
                                       : "major diameter d of an external thread");
  Refuse(shown, "ISO 965-1 has no tolerance grade " + std::to_string(grade) + " for the " + what +
                    " (grades " + GradeList(steps) + ")");
}

}  // namespace

double FundamentalTriangleHeight(double pitch) { return std::sqrt(3.0) / 2.0 * pitch; }

// ISO 68-1: d2 = d - 2 (3/8) H, d1 = d - 2 (5/8) H, d3 = d1 - H/6 (the root rounding of the
// bolt), i.e. 0.649519 P, 1.082532 P and 1.226869 P below d.
double BasicPitchDiameter(double nominal, double pitch) {
  return nominal - 0.75 * FundamentalTriangleHeight(pitch);
}
double BasicMinorDiameter(double nominal, double pitch) {
  return nominal - 1.25 * FundamentalTriangleHeight(pitch);
}
double BasicRootDiameter(double nominal, double pitch) {
  return BasicMinorDiameter(nominal, pitch) - FundamentalTriangleHeight(pitch) / 6.0;
}

bool LooksLikeThread(std::string_view text) {
  text = Trim(text);
  return text.size() >= 2 && text[0] == 'M' && std::isdigit(static_cast<unsigned char>(text[1]));
}

ThreadSize ParseThreadSize(std::string_view text) {
  const std::string_view trimmed = Trim(text);
  return ParseSizeIn(trimmed, trimmed);
}

ThreadDesignation ParseDesignation(std::string_view text) {
  const std::string_view shown = Trim(text);
  const std::size_t split = shown.find_first_of(" \t-");
  if (split == std::string_view::npos) {
    Refuse(shown,
           "expected a size and a tolerance class (e.g. 'M10x1.5 6g', 'M10 6H'), found no "
           "class");
  }
  ThreadDesignation designation;
  designation.size = ParseSizeIn(shown.substr(0, split), shown);
  std::string_view rest = shown.substr(split);
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  if (!rest.empty() && rest.front() == '-') rest.remove_prefix(1);
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  const std::string whole(rest);
  char position = 'h';
  TakePart(rest, shown, whole, &designation.pitch_grade, &position);
  designation.crest_grade = designation.pitch_grade;
  if (!rest.empty()) {
    char crest_position = 'h';
    TakePart(rest, shown, whole, &designation.crest_grade, &crest_position);
    if (crest_position != position) {
      Refuse(shown, "the pitch and crest diameter classes of '" + whole +
                        "' must have the same tolerance position, found '" +
                        std::string(1, position) + "' and '" + std::string(1, crest_position) +
                        "'");
    }
  }
  if (!rest.empty()) {
    Refuse(shown, "expected a tolerance class such as 6g, 6H or 5g6g after the size, found '" +
                      whole + "'");
  }
  designation.position = position;
  designation.internal = std::isupper(static_cast<unsigned char>(position)) != 0;
  CheckGrade(shown, designation.pitch_grade, designation.internal, true);
  CheckGrade(shown, designation.crest_grade, designation.internal, false);
  designation.pitch_diameter_class = std::to_string(designation.pitch_grade) + position;
  designation.crest_diameter_class = std::to_string(designation.crest_grade) + position;
  designation.tolerance_class =
      designation.pitch_grade == designation.crest_grade
          ? designation.pitch_diameter_class
          : designation.pitch_diameter_class + designation.crest_diameter_class;
  designation.text = designation.size.text + " " + designation.tolerance_class;
  return designation;
}

ThreadLimits Lookup(const ThreadDesignation& designation) {
  const ThreadSize& size = designation.size;
  const double nominal_mm = size.nominal / kMetresPerMillimetre;
  const double pitch_mm = size.pitch / kMetresPerMillimetre;
  const t::PitchRow& row = FindPitchRow(pitch_mm);
  const int range = FindRange(nominal_mm);
  const double td26 = Td2Grade6(range, pitch_mm);
  const auto refuse = [&](const std::string& why) { Refuse(designation.text, why); };
  const int pitch_grade = designation.pitch_grade;
  const int crest_grade = designation.crest_grade;

  // ISO 965-1 leaves the coarsest grades out at fine pitches (blank table cells).
  const bool fine = pitch_mm < 0.8 - kSameMm;
  const bool very_fine = pitch_mm < 0.5 - kSameMm;
  ThreadLimits limits;
  limits.designation = designation;
  limits.range_lower = t::kRanges[range].lower_mm * kMetresPerMillimetre;
  limits.range_upper = t::kRanges[range].upper_mm * kMetresPerMillimetre;
  const double d = size.nominal;
  const double p = size.pitch;
  constexpr double kOpen = std::numeric_limits<double>::infinity();
  if (designation.internal) {
    if ((pitch_grade == 8 && fine) || (pitch_grade == 7 && very_fine)) {
      refuse("ISO 965-1 tabulates TD2 grade " + std::to_string(pitch_grade) + " from a pitch of " +
             (pitch_grade == 8 ? "0.8" : "0.5") + " mm on, found " + Mm(pitch_mm) + " mm");
    }
    if ((crest_grade == 8 && fine) || (crest_grade == 7 && very_fine)) {
      refuse("ISO 965-1 tabulates TD1 grade " + std::to_string(crest_grade) + " from a pitch of " +
             (crest_grade == 8 ? "0.8" : "0.5") + " mm on, found " + Mm(pitch_mm) + " mm");
    }
    const double ei = designation.position == 'G' ? row.ei_g_um : 0.0;
    const double td2 = GradeValue(td26, kTD2Steps, pitch_grade);
    const double td1 = GradeValue(row.td16_um, kTd1Steps, crest_grade);
    limits.fundamental_deviation = ei * kMetresPerMicrometre;
    limits.pitch_tolerance = td2 * kMetresPerMicrometre;
    limits.crest_tolerance = td1 * kMetresPerMicrometre;
    limits.major = {d, limits.fundamental_deviation, kOpen};
    limits.pitch_diameter = {BasicPitchDiameter(d, p), limits.fundamental_deviation,
                             (ei + td2) * kMetresPerMicrometre};
    limits.minor = {BasicMinorDiameter(d, p), limits.fundamental_deviation,
                    (ei + td1) * kMetresPerMicrometre};
    return limits;
  }
  if (pitch_grade >= 8 && fine) {
    refuse("ISO 965-1 tabulates Td2 grade " + std::to_string(pitch_grade) +
           " from a pitch of 0.8 mm on, found " + Mm(pitch_mm) + " mm");
  }
  double es = 0.0;
  switch (designation.position) {
    case 'e':
      if (very_fine) {
        refuse("ISO 965-1 defines tolerance position e from a pitch of 0.5 mm on, found " +
               Mm(pitch_mm) + " mm");
      }
      es = row.es_e_um;
      break;
    case 'f':
      es = row.es_f_um;
      break;
    case 'g':
      es = row.es_g_um;
      break;
    default:
      break;
  }
  const double td2 = GradeValue(td26, kTd2Steps, pitch_grade);
  const double td = GradeValue(row.td6_um, kTdSteps, crest_grade);
  limits.fundamental_deviation = es * kMetresPerMicrometre;
  limits.pitch_tolerance = td2 * kMetresPerMicrometre;
  limits.crest_tolerance = td * kMetresPerMicrometre;
  limits.major = {d, (es - td) * kMetresPerMicrometre, limits.fundamental_deviation};
  limits.pitch_diameter = {BasicPitchDiameter(d, p), (es - td2) * kMetresPerMicrometre,
                           limits.fundamental_deviation};
  limits.minor = {BasicRootDiameter(d, p), -kOpen, limits.fundamental_deviation};
  limits.flat_minor_max = BasicMinorDiameter(d, p) + limits.fundamental_deviation;
  return limits;
}

}  // namespace fitfeel::iso965
