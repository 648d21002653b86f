#pragma once

// Fundamental deviations of holes, ISO 286-1 Table 3, for nominal sizes up to 500 mm, in
// micrometres. Most of Table 3 is the shaft table mirrored by the standard's rules (EI = -es for
// A to H; ES = -ei for K to ZC, plus Delta for K, M, N up to IT8 and P to ZC up to IT7); those
// rules live in the lookup. This file holds what Table 3 gives that the mirror does not: the J
// columns, the Delta columns, the K and N columns for grades above IT8, and the special case of M6.

#include <array>

#include "framework/iso286/shaft_deviation_table.h"
#include "framework/iso286/size_steps_table.h"

namespace fitfeel::iso286::tables {

// Upper deviations ES of the hole J; J is defined for IT6, IT7 and IT8 only.
enum HoleJColumn { kJ6, kJ7Hole, kJ8Hole, kHoleJColumnCount };

// One row per main step (kMainStepUpperMm).
// clang-format off
inline constexpr std::array<std::array<double, kHoleJColumnCount>, kMainStepCount> kHoleJUpperDeviationUm = {{
  //  J6  J7  J8
  {{   2,  4,  6}},  //   0-3
  {{   5,  6, 10}},  //   3-6
  {{   5,  8, 12}},  //   6-10
  {{   6, 10, 15}},  //  10-18
  {{   8, 12, 20}},  //  18-30
  {{  10, 14, 24}},  //  30-50
  {{  13, 18, 28}},  //  50-80
  {{  16, 22, 34}},  //  80-120
  {{  18, 26, 41}},  // 120-180
  {{  22, 30, 47}},  // 180-250
  {{  25, 36, 55}},  // 250-315
  {{  29, 39, 60}},  // 315-400
  {{  33, 43, 66}},  // 400-500
}};
// clang-format on

// Delta = ITn - IT(n-1), added to ES of K, M, N up to IT8 and of P to ZC up to IT7 so that a hole-
// basis fit (H7/p6) and the shaft-basis fit of the same letters (P7/h6) have the same clearances.
// The standard tabulates it for IT3 to IT8 only (0 in the first step); a class that needs Delta at
// a finer grade is outside the tables. One row per main step.
inline constexpr int kDeltaFirstGrade = 3;
inline constexpr int kDeltaLastGrade = 8;
// clang-format off
inline constexpr std::array<std::array<double, kDeltaLastGrade - kDeltaFirstGrade + 1>, kMainStepCount> kDeltaUm = {{
  // IT3  IT4  IT5 IT6 IT7 IT8
  {{ 0,   0,   0,  0,  0,  0}},   //   0-3
  {{ 1,   1.5, 1,  3,  4,  6}},   //   3-6
  {{ 1,   1.5, 2,  3,  6,  7}},   //   6-10
  {{ 1,   2,   3,  3,  7,  9}},   //  10-18
  {{ 1.5, 2,   3,  4,  8, 12}},   //  18-30
  {{ 1.5, 3,   4,  5,  9, 14}},   //  30-50
  {{ 2,   3,   5,  6, 11, 16}},   //  50-80
  {{ 2,   4,   5,  7, 13, 19}},   //  80-120
  {{ 3,   4,   6,  7, 15, 23}},   // 120-180
  {{ 3,   4,   6,  9, 17, 26}},   // 180-250
  {{ 4,   4,   7,  9, 20, 29}},   // 250-315
  {{ 4,   5,   7, 11, 21, 32}},   // 315-400
  {{ 5,   5,   7, 13, 23, 34}},   // 400-500
}};
// clang-format on

// ES of K for grades above IT8: 0 up to 3 mm, not defined above 3 mm (Table 3 leaves it empty).
inline constexpr std::array<double, kMainStepCount> kHoleKAboveIT8UpperDeviationUm = {
    0,      kBlank, kBlank, kBlank, kBlank, kBlank, kBlank,
    kBlank, kBlank, kBlank, kBlank, kBlank, kBlank};

// ES of N for grades above IT8: -4 up to 3 mm, 0 above. Not used up to and including 1 mm (footnote
// to Table 3; the lookup refuses it there).
inline constexpr std::array<double, kMainStepCount> kHoleNAboveIT8UpperDeviationUm = {
    -4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};

// Special case of Table 3: M6 from 250 mm to 315 mm has ES = -9 um (the rule would give -11 um).
inline constexpr int kM6SpecialCaseMainStep = 10;  // 250-315 mm
inline constexpr double kM6SpecialCaseUpperDeviationUm = -9;

}  // namespace fitfeel::iso286::tables
