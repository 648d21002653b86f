#pragma once

// Standard tolerance values IT01 to IT18 for nominal sizes up to 500 mm, in micrometres: ISO 286-1
// Table 1 (IT1-IT18) and the table of IT01 and IT0 (ISO 286-1:1988 Table 5). The formula
// i = 0.45 D^(1/3) + 0.001 D does not reproduce these values (the standard rounds them by its own
// rules), so they are carried as data; the formula is only a cross-check in the tests.
// IT14 to IT18 are not used for nominal sizes up to and including 1 mm (note to Table 1).

#include <array>

#include "framework/iso286/size_steps_table.h"

namespace fitfeel::iso286::tables {

// Column index of a grade: 0 = IT01, 1 = IT0, n + 1 = ITn for n = 1..18.
inline constexpr int kGradeCount = 20;

// One row per main step (kMainStepUpperMm).
// clang-format off
inline constexpr std::array<std::array<double, kGradeCount>, kMainStepCount> kStandardToleranceUm = {{
  //  IT01 IT0  IT1  IT2  IT3  IT4 IT5 IT6 IT7 IT8 IT9  IT10 IT11 IT12 IT13 IT14  IT15  IT16  IT17  IT18
  {{  0.3, 0.5, 0.8, 1.2, 2,   3,  4,  6,  10, 14,  25,  40,  60, 100, 140,  250,  400,  600, 1000, 1400}},  //   0-3
  {{  0.4, 0.6, 1,   1.5, 2.5, 4,  5,  8,  12, 18,  30,  48,  75, 120, 180,  300,  480,  750, 1200, 1800}},  //   3-6
  {{  0.4, 0.6, 1,   1.5, 2.5, 4,  6,  9,  15, 22,  36,  58,  90, 150, 220,  360,  580,  900, 1500, 2200}},  //   6-10
  {{  0.5, 0.8, 1.2, 2,   3,   5,  8,  11, 18, 27,  43,  70, 110, 180, 270,  430,  700, 1100, 1800, 2700}},  //  10-18
  {{  0.6, 1,   1.5, 2.5, 4,   6,  9,  13, 21, 33,  52,  84, 130, 210, 330,  520,  840, 1300, 2100, 3300}},  //  18-30
  {{  0.6, 1,   1.5, 2.5, 4,   7,  11, 16, 25, 39,  62, 100, 160, 250, 390,  620, 1000, 1600, 2500, 3900}},  //  30-50
  {{  0.8, 1.2, 2,   3,   5,   8,  13, 19, 30, 46,  74, 120, 190, 300, 460,  740, 1200, 1900, 3000, 4600}},  //  50-80
  {{  1,   1.5, 2.5, 4,   6,   10, 15, 22, 35, 54,  87, 140, 220, 350, 540,  870, 1400, 2200, 3500, 5400}},  //  80-120
  {{  1.2, 2,   3.5, 5,   8,   12, 18, 25, 40, 63, 100, 160, 250, 400, 630, 1000, 1600, 2500, 4000, 6300}},  // 120-180
  {{  2,   3,   4.5, 7,   10,  14, 20, 29, 46, 72, 115, 185, 290, 460, 720, 1150, 1850, 2900, 4600, 7200}},  // 180-250
  {{  2.5, 4,   6,   8,   12,  16, 23, 32, 52, 81, 130, 210, 320, 520, 810, 1300, 2100, 3200, 5200, 8100}},  // 250-315
  {{  3,   5,   7,   9,   13,  18, 25, 36, 57, 89, 140, 230, 360, 570, 890, 1400, 2300, 3600, 5700, 8900}},  // 315-400
  {{  4,   6,   8,   10,  15,  20, 27, 40, 63, 97, 155, 250, 400, 630, 970, 1550, 2500, 4000, 6300, 9700}},  // 400-500
}};
// clang-format on

}  // namespace fitfeel::iso286::tables
