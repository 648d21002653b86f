#include "framework/iso286/iso286.h"

#include <array>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "framework/iso286/hole_deviation_table.h"
#include "framework/iso286/shaft_deviation_table.h"
#include "framework/iso286/size_steps_table.h"
#include "framework/iso286/standard_tolerance_table.h"

namespace fitfeel::iso286 {
namespace {

namespace t = tables;

// Sizes are given in metres and compared with step bounds in millimetres; a size within this
// distance of a bound is taken as on it, so that 0.03 m * 1000 lands in 18-30 mm whatever the
// rounding of the product.
constexpr double kBoundarySlackMm = 1e-9;
constexpr double kLargestSizeMm = 500.0;

// Letters in the order of ISO 286-1 (lower case; the hole is the same letter in upper case).
constexpr std::array<std::string_view, 28> kLetters = {
    "a", "b", "c", "cd", "d", "e", "ef", "f", "fg", "g", "h", "js", "j",  "k",
    "m", "n", "p", "r",  "s", "t", "u",  "v", "x",  "y", "z", "za", "zb", "zc"};

std::string FormatMm(double mm) {
  std::ostringstream out;
  out.precision(6);
  out << mm;
  return out.str();
}

std::string LetterList(bool upper) {
  std::string list;
  for (std::string_view letter : kLetters) {
    if (!list.empty()) list += ' ';
    for (char c : letter) list += upper ? static_cast<char>(c - 'a' + 'A') : c;
  }
  return list;
}

struct Code {
  std::string letter;  // lower case
  bool is_hole = false;
  int grade = 0;  // -1 = IT01, 0 = IT0, n = ITn
  std::string normalised;
};

// Column of a grade in kStandardToleranceUm.
int GradeColumn(int grade) { return grade + 1; }

Code ParseCode(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  const std::string shown(text);
  std::size_t split = 0;
  while (split < text.size() && std::isalpha(static_cast<unsigned char>(text[split]))) ++split;
  const std::string_view letters = text.substr(0, split);
  const std::string_view digits = text.substr(split);
  if (letters.empty()) {
    throw std::invalid_argument("ISO 286 tolerance class '" + shown +
                                "' has no fundamental deviation letter (expected e.g. H7, g6, "
                                "js6)");
  }
  bool all_upper = true;
  bool all_lower = true;
  std::string lower;
  for (char c : letters) {
    const bool up = std::isupper(static_cast<unsigned char>(c)) != 0;
    all_upper = all_upper && up;
    all_lower = all_lower && !up;
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  bool known = all_upper || all_lower;
  if (known) {
    known = false;
    for (std::string_view letter : kLetters) known = known || letter == lower;
  }
  if (!known) {
    throw std::invalid_argument("unknown ISO 286 fundamental deviation '" + std::string(letters) +
                                "' in '" + shown + "' (holes: " + LetterList(true) +
                                "; shafts: " + LetterList(false) + ")");
  }
  int grade = -2;
  if (digits == "01") {
    grade = -1;
  } else if (!digits.empty() && digits.size() <= 2 &&
             std::isdigit(static_cast<unsigned char>(digits[0])) &&
             (digits.size() == 1 || std::isdigit(static_cast<unsigned char>(digits[1]))) &&
             !(digits.size() == 2 && digits[0] == '0')) {
    grade = std::stoi(std::string(digits));
    if (grade > 18) grade = -2;
  }
  if (grade == -2) {
    throw std::invalid_argument(
        digits.empty() ? "ISO 286 tolerance class '" + shown + "' has no grade (expected e.g. " +
                             std::string(letters) + "7)"
                       : "unknown ISO 286 standard tolerance grade '" + std::string(digits) +
                             "' in '" + shown + "' (grades are 01, 0 and 1 to 18)");
  }
  return Code{lower, all_upper, grade, std::string(letters) + std::string(digits)};
}

// Index of the step holding a size: the first step whose upper bound is not below it.
template <std::size_t N>
int StepIndex(const std::array<double, N>& upper_bounds_mm, double mm) {
  for (std::size_t i = 0; i < N; ++i) {
    if (mm <= upper_bounds_mm[i] + kBoundarySlackMm) return static_cast<int>(i);
  }
  return static_cast<int>(N) - 1;  // unreachable: sizes are checked against 500 mm first
}

template <std::size_t N>
double StepLower(const std::array<double, N>& upper_bounds_mm, int index) {
  return index == 0 ? 0.0 : upper_bounds_mm[index - 1];
}

// Everything the rules below need about the request, and the message for a refusal.
struct Request {
  Code code;
  double mm = 0.0;
  int main = 0;  // index into kMainStepUpperMm
  int fine = 0;  // index into kFineStepUpperMm
  double it = 0.0;

  [[noreturn]] void Undefined(const std::string& why) const {
    throw std::invalid_argument("ISO 286 does not define " + code.normalised + " at " +
                                FormatMm(mm) + " mm (size step " +
                                FormatMm(StepLower(t::kFineStepUpperMm, fine)) + "-" +
                                FormatMm(t::kFineStepUpperMm[fine]) + " mm): " + why);
  }
};

struct Deviations {
  double lower = 0.0;
  double upper = 0.0;
};

// js / JS: +-IT/2. For grades 7 to 11 an odd IT value is rounded down to the next even number
// first, so that the deviations are whole micrometres (footnote to ISO 286-1 Tables 2 and 3, which
// ISO 286-2 applies: js7 in 18-30 mm is +-10 um, not +-10.5 um).
Deviations Symmetric(const Request& r) {
  double it = r.it;
  if (r.code.grade >= 7 && r.code.grade <= 11 && std::fmod(it, 2.0) == 1.0) it -= 1.0;
  return {-it / 2.0, it / 2.0};
}

int UpperColumn(std::string_view letter) {
  constexpr std::array<std::string_view, t::kShaftUpperColumnCount> kNames = {
      "a", "b", "c", "cd", "d", "e", "ef", "f", "fg", "g", "h"};
  for (int i = 0; i < t::kShaftUpperColumnCount; ++i) {
    if (kNames[i] == letter) return i;
  }
  return -1;
}

int LowerColumn(std::string_view letter) {
  constexpr std::array<std::string_view, t::kShaftLowerColumnCount> kNames = {
      "", "", "", "", "m", "n", "p", "r", "s", "t", "u", "v", "x", "y", "z", "za", "zb", "zc"};
  for (int i = 0; i < t::kShaftLowerColumnCount; ++i) {
    if (!kNames[i].empty() && kNames[i] == letter) return i;
  }
  return -1;
}

// es of the shafts a to h (also the mirror of EI for A to H).
double ShaftUpperFundamental(const Request& r, int column) {
  if ((column == t::kA || column == t::kB) && r.mm <= 1.0 + kBoundarySlackMm) {
    r.Undefined("the fundamental deviations a, b, A and B are not used for sizes up to 1 mm");
  }
  const double es = t::kShaftUpperDeviationUm[r.fine][column];
  if (std::isnan(es)) {
    r.Undefined(
        "the intermediate deviations cd, ef, fg (CD, EF, FG) are tabulated up to 10 mm only");
  }
  return es;
}

// ei of the shafts m to zc (also the mirror of ES for M to ZC).
double ShaftLowerFundamental(const Request& r, int column) {
  const double ei = t::kShaftLowerDeviationUm[r.fine][column];
  if (std::isnan(ei)) {
    r.Undefined("the table of fundamental deviations has no value for '" + r.code.letter +
                "' in this size step");
  }
  return ei;
}

double Delta(const Request& r) {
  if (r.code.grade < t::kDeltaFirstGrade) {
    r.Undefined("its upper deviation needs Delta, which ISO 286-1 tabulates for IT3 to IT8 only");
  }
  return t::kDeltaUm[r.main][r.code.grade - t::kDeltaFirstGrade];
}

Deviations ShaftDeviations(const Request& r) {
  const std::string& letter = r.code.letter;
  const int grade = r.code.grade;
  if (letter == "js") return Symmetric(r);
  if (const int column = UpperColumn(letter); column >= 0) {
    const double es = ShaftUpperFundamental(r, column);
    return {es - r.it, es};
  }
  double ei = 0.0;
  if (letter == "j") {
    int column = -1;
    if (grade == 5 || grade == 6) column = t::kJ5J6;
    if (grade == 7) column = t::kJ7;
    if (grade == 8) column = t::kJ8;
    if (column < 0) r.Undefined("j is defined for IT5 to IT8 only (use js)");
    ei = t::kShaftLowerDeviationUm[r.fine][column];
    if (std::isnan(ei)) r.Undefined("j8 is defined up to 3 mm only (use js)");
  } else if (letter == "k") {
    ei = (grade >= 4 && grade <= 7) ? t::kShaftLowerDeviationUm[r.fine][t::kK4To7] : 0.0;
  } else {
    ei = ShaftLowerFundamental(r, LowerColumn(letter));
  }
  return {ei, ei + r.it};
}

Deviations HoleDeviations(const Request& r) {
  const std::string& letter = r.code.letter;
  const int grade = r.code.grade;
  if (letter == "js") return Symmetric(r);
  if (const int column = UpperColumn(letter); column >= 0) {
    const double ei = -ShaftUpperFundamental(r, column);
    return {ei, ei + r.it};
  }
  double es = 0.0;
  if (letter == "j") {
    if (grade < 6 || grade > 8) r.Undefined("J is defined for IT6 to IT8 only (use JS)");
    es = t::kHoleJUpperDeviationUm[r.main][grade - 6];
  } else if (letter == "k") {
    if (grade <= 8) {
      es = -t::kShaftLowerDeviationUm[r.fine][t::kK4To7] + Delta(r);
    } else {
      es = t::kHoleKAboveIT8UpperDeviationUm[r.main];
      if (std::isnan(es)) r.Undefined("K above IT8 is defined up to 3 mm only");
    }
  } else if (letter == "m") {
    const double m = t::kShaftLowerDeviationUm[r.fine][t::kM];
    if (grade == 6 && r.main == t::kM6SpecialCaseMainStep) {
      es = t::kM6SpecialCaseUpperDeviationUm;
    } else {
      es = grade <= 8 ? -m + Delta(r) : -m;
    }
  } else if (letter == "n") {
    if (grade <= 8) {
      es = -t::kShaftLowerDeviationUm[r.fine][t::kN] + Delta(r);
    } else {
      if (r.mm <= 1.0 + kBoundarySlackMm) {
        r.Undefined("N above IT8 is not used for sizes up to 1 mm");
      }
      es = t::kHoleNAboveIT8UpperDeviationUm[r.main];
    }
  } else {
    const double ei = ShaftLowerFundamental(r, LowerColumn(letter));
    es = grade <= 7 ? -ei + Delta(r) : -ei;
  }
  return {es - r.it, es};
}

}  // namespace

Limits Lookup(double nominal_m, std::string_view code_text) {
  const Code code = ParseCode(code_text);
  const double mm = nominal_m * 1e3;
  if (!std::isfinite(nominal_m) || !(mm > 0.0) || mm > kLargestSizeMm + kBoundarySlackMm) {
    throw std::invalid_argument("nominal size " + FormatMm(mm) + " mm for " + code.normalised +
                                " is outside the ISO 286 tables (0 mm, 500 mm]");
  }
  Request r;
  r.code = code;
  r.mm = mm;
  r.main = StepIndex(t::kMainStepUpperMm, mm);
  r.fine = StepIndex(t::kFineStepUpperMm, mm);
  r.it = t::kStandardToleranceUm[r.main][GradeColumn(code.grade)];
  if (code.grade >= 14 && mm <= 1.0 + kBoundarySlackMm) {
    r.Undefined("IT14 to IT18 are not used for sizes up to 1 mm");
  }
  const Deviations d = code.is_hole ? HoleDeviations(r) : ShaftDeviations(r);

  constexpr double kMetresPerMicrometre = 1e-6;
  Limits limits;
  limits.nominal = nominal_m;
  limits.lower_deviation = d.lower * kMetresPerMicrometre;
  limits.upper_deviation = d.upper * kMetresPerMicrometre;
  limits.it = r.it * kMetresPerMicrometre;
  limits.is_hole = code.is_hole;
  limits.code = code.normalised;
  limits.step_lower = StepLower(t::kMainStepUpperMm, r.main) * 1e-3;
  limits.step_upper = t::kMainStepUpperMm[r.main] * 1e-3;
  return limits;
}

}  // namespace fitfeel::iso286
